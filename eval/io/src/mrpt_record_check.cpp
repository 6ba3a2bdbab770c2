#include "mrpt_record_check.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <string_view>

namespace relslam::eval {
namespace {

// Sane maxima for counts that have no business being large (the record limit bounds the rest).
constexpr std::uint32_t kMaxObjectsPerContainer = 65536;  // observations in a frame, actions in a collection
constexpr std::uint32_t kMaxLabelBytes = 4096;            // sensor labels
constexpr std::uint32_t kMaxSmallVector = 64;             // 6D velocity flags and values
constexpr std::int32_t kMaxThrunParticles = 100000;       // MRPT draws this many samples (default 300)
constexpr std::size_t kReadChunk = std::size_t{1} << 20;  // never allocate ahead of the input by more

enum class Class {
  SensoryFrame,
  ActionCollection,
  BearingRange,
  RangeScan2D,
  Odometry,
  RobotMovement2D,
  RobotMovement3D,
  Pose2D,
  Pose3D,
  PosePdfGaussian,
  Pose3DPdfGaussian,
  MatrixD,
};

struct ClassInfo {
  Class id;
  const char* name;        // as MRPT 2 writes it without its namespace (older MRPT wrote only this)
  const char* namespace_;  // what MRPT 2 writes before it
};

constexpr std::array kClasses = {
    ClassInfo{Class::SensoryFrame, "CSensoryFrame", "mrpt::obs::"},
    ClassInfo{Class::ActionCollection, "CActionCollection", "mrpt::obs::"},
    ClassInfo{Class::BearingRange, "CObservationBearingRange", "mrpt::obs::"},
    ClassInfo{Class::RangeScan2D, "CObservation2DRangeScan", "mrpt::obs::"},
    ClassInfo{Class::Odometry, "CObservationOdometry", "mrpt::obs::"},
    ClassInfo{Class::RobotMovement2D, "CActionRobotMovement2D", "mrpt::obs::"},
    ClassInfo{Class::RobotMovement3D, "CActionRobotMovement3D", "mrpt::obs::"},
    ClassInfo{Class::Pose2D, "CPose2D", "mrpt::poses::"},
    ClassInfo{Class::Pose3D, "CPose3D", "mrpt::poses::"},
    ClassInfo{Class::PosePdfGaussian, "CPosePDFGaussian", "mrpt::poses::"},
    ClassInfo{Class::Pose3DPdfGaussian, "CPose3DPDFGaussian", "mrpt::poses::"},
    ClassInfo{Class::MatrixD, "CMatrixD", "mrpt::math::"},
};

const ClassInfo& info(Class c) {
  return *std::find_if(kClasses.begin(), kClasses.end(), [c](const ClassInfo& i) { return i.id == c; });
}

std::string names_of(std::initializer_list<Class> classes) {
  std::string text;
  for (Class c : classes) text += (text.empty() ? "" : ", ") + std::string(info(c).name);
  return text;
}

constexpr std::initializer_list<Class> kTopLevel = {Class::ActionCollection, Class::SensoryFrame, Class::BearingRange,
                                                    Class::RangeScan2D, Class::Odometry};
constexpr std::initializer_list<Class> kInFrame = {Class::BearingRange, Class::RangeScan2D, Class::Odometry};
constexpr std::initializer_list<Class> kInCollection = {Class::RobotMovement2D, Class::RobotMovement3D};

// The class-name length an object header's first byte gives; throws when it is no MRPT header.
unsigned class_name_length(std::uint8_t length_byte, const std::string& path) {
  if (!(length_byte & 0x80))
    throw RecordProblem(path, "no MRPT object header here (first byte " + std::to_string(length_byte) +
                                  "; objects written before MRPT 0.5.5 are not read)");
  const unsigned length = length_byte & 0x7F;
  if (length == 0 || length > 120)
    throw RecordProblem(path, "class name of " + std::to_string(length) + " characters: not an MRPT object");
  return length;
}

void require_identifier(const std::string& name, const std::string& path) {
  if (!std::all_of(name.begin(), name.end(), [](char ch) {
        return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '_' ||
               ch == ':';
      }))
    throw RecordProblem(path, "the class name is not an identifier: not an MRPT object");
}

class Walker {
 public:
  Walker(const ByteReader& read, std::vector<unsigned char>& out) : read_(read), out_(out) {}

  // One object of one of `allowed`; `path` names where it sits.
  void object(const std::string& path, std::initializer_list<Class> allowed, unsigned matrix_rows = 0,
              unsigned matrix_cols = 0) {
    const std::uint8_t length_byte = pod<std::uint8_t>(path, "object header");
    const unsigned length = class_name_length(length_byte, path);
    need(length, path, "class name");
    const std::string name(reinterpret_cast<const char*>(out_.data() + out_.size() - length), length);
    require_identifier(name, path);
    const ClassInfo* found = nullptr;
    for (Class c : allowed)
      if (name == info(c).name || name == std::string(info(c).namespace_) + info(c).name) found = &info(c);
    if (!found)
      throw RecordProblem(path, "class " + name + " is not accepted here (accepted: " + names_of(allowed) + ")");
    const std::string here = path.empty() ? found->name : path + "." + found->name;
    const unsigned version = pod<std::uint8_t>(here, "version");
    payload(found->id, version, here, matrix_rows, matrix_cols);
    if (pod<std::uint8_t>(here, "end flag") != 0x88)
      throw RecordProblem(here, "no end flag after the object's fields (corrupt record)");
  }

 private:
  void unsupported(const std::string& path, unsigned version) {
    throw RecordProblem(path, "serialisation version " + std::to_string(version) + " is not read");
  }

  // The fields of one object of class c, serialisation version v (MRPT 2's readers): one
  // function per class, each reading what MRPT's serializeFrom reads.
  void payload(Class c, unsigned v, const std::string& path, unsigned matrix_rows, unsigned matrix_cols) {
    switch (c) {
      case Class::SensoryFrame: return sensory_frame(v, path);
      case Class::ActionCollection: return action_collection(v, path);
      case Class::BearingRange: return bearing_range(v, path);
      case Class::RangeScan2D: return range_scan_2d(v, path);
      case Class::Odometry: return odometry(v, path);
      case Class::RobotMovement2D: return robot_movement_2d(v, path);
      case Class::RobotMovement3D: return robot_movement_3d(v, path);
      case Class::Pose2D: return pose_2d(v, path);
      case Class::Pose3D: return pose_3d(v, path);
      case Class::PosePdfGaussian: return pose_pdf_gaussian(v, path);
      case Class::Pose3DPdfGaussian: return pose_3d_pdf_gaussian(v, path);
      case Class::MatrixD: return matrix(v, path, matrix_rows, matrix_cols);
    }
  }

  void sensory_frame(unsigned v, const std::string& path) {
    if (v > 2) unsupported(path, v);
    if (v < 2) skip(4, path, "ID");
    if (v == 0) skip(8, path, "timestamp");
    const std::uint32_t n = count(path + ".observations", kMaxObjectsPerContainer);
    for (std::uint32_t i = 0; i < n; ++i) object(path + ".observations[" + std::to_string(i) + "]", kInFrame);
  }

  void action_collection(unsigned v, const std::string& path) {
    if (v != 0) unsupported(path, v);
    const std::uint32_t n = count(path + ".actions", kMaxObjectsPerContainer);
    for (std::uint32_t i = 0; i < n; ++i) object(path + ".actions[" + std::to_string(i) + "]", kInCollection);
  }

  void bearing_range(unsigned v, const std::string& path) {
    if (v > 3) unsupported(path, v);
    skip(v >= 3 ? 16 : 12, path, "sensor limits");
    object(path + ".sensorLocationOnRobot", {Class::Pose3D});
    if (v >= 2) skip(8, path, "timestamp");
    const bool covariances = v >= 3 && boolean(path + ".validCovariances");
    if (v >= 3 && !covariances) skip(12, path, "sensor std");
    const std::string field = path + ".sensedData";
    const std::uint32_t n = count(field, UINT32_MAX, 16);
    for (std::uint32_t i = 0; i < n; ++i) {
      skip(16, field, "range, yaw, pitch, id");
      if (covariances) object(field + "[" + std::to_string(i) + "].covariance", {Class::MatrixD}, 3, 3);
    }
    if (v >= 1) string(path + ".sensorLabel");
  }

  void odometry(unsigned v, const std::string& path) {
    if (v > 2) unsupported(path, v);
    object(path + ".odometry", {Class::Pose2D});
    string(path + ".sensorLabel");
    skip(8, path, "timestamp");
    if (v >= 1) {
      if (boolean(path + ".hasEncodersInfo") || v < 2) skip(8, path, "encoder ticks");
      const bool velocities = boolean(path + ".hasVelocities");
      if (v < 2)
        skip(8, path, "velocities");
      else if (velocities)
        skip(24, path, "velocityLocal");
    }
  }

  void robot_movement_2d(unsigned v, const std::string& path) {
    // Versions 0 and 1 (MRPT before 0.9) put the pose PDF first; not read.
    if (v < 2 || v > 7) unsupported(path, v);
    const std::int32_t method = pod<std::int32_t>(path, "estimationMethod");
    if (method != 0 && method != 1)
      throw RecordProblem(path + ".estimationMethod",
                          "must be 0 (odometry) or 1 (scan matching), got " + std::to_string(method));
    if (method == 0) {  // odometry: MRPT recomputes the PDF from the reading and the model
      object(path + ".rawOdometryIncrementReading", {Class::Pose2D});
      if (v == 2) {
        skip(44, path, "motion model");
      } else {
        const std::int32_t model = pod<std::int32_t>(path, "modelSelection");
        if (model != 0 && model != 1)
          throw RecordProblem(path + ".modelSelection",
                              "must be 0 (Gaussian) or 1 (Thrun), got " + std::to_string(model));
        skip(v >= 4 ? 24 : 20, path, "Gaussian model");
        const std::int32_t particles = pod<std::int32_t>(path, "nParticlesCount");
        if (model == 1 && (particles < 1 || particles > kMaxThrunParticles))
          throw RecordProblem(path + ".nParticlesCount", "must be in [1, " + std::to_string(kMaxThrunParticles) +
                                                             "] for the Thrun model, got " +
                                                             std::to_string(particles));
        skip(v >= 5 ? 24 : 16, path, "Thrun model");
      }
    } else {
      object(path + ".poseChange", {Class::PosePdfGaussian});
    }
    // Before version 7 both flags are followed by their fields whatever they say, and
    // MRPT of that time wrote them uninitialised (localization_demo.rawlog holds 90 and 8,
    // and MRPT reads the file): normalised to 0 or 1 for MRPT's reader, which ignores them.
    const bool velocities = v < 7 ? legacy_flag(path + ".hasVelocities") : boolean(path + ".hasVelocities");
    if (v < 7)
      skip(8, path, "velocities");
    else if (velocities)
      skip(24, path, "velocityLocal");
    if (v < 7) {
      legacy_flag(path + ".hasEncodersInfo");
      skip(8, path, "encoder ticks");
    } else if (boolean(path + ".hasEncodersInfo")) {
      skip(8, path, "encoder ticks");
    }
    if (v >= 6) skip(8, path, "timestamp");
  }

  void robot_movement_3d(unsigned v, const std::string& path) {
    if (v > 1) unsupported(path, v);
    const std::uint32_t method = pod<std::uint32_t>(path, "estimationMethod");
    if (method > 1)
      throw RecordProblem(path + ".estimationMethod",
                          "must be 0 (odometry) or 1 (visual odometry), got " + std::to_string(method));
    object(path + ".poseChange", {Class::Pose3DPdfGaussian});
    const std::uint32_t flags = count(path + ".hasVelocities", kMaxSmallVector, 1);
    for (std::uint32_t i = 0; i < flags; ++i) boolean(path + ".hasVelocities");
    const std::uint32_t values = count(path + ".velocities", kMaxSmallVector, 4);
    skip(4 * std::size_t{values}, path, "velocities");
    if (v >= 1) skip(8, path, "timestamp");
  }

  void pose_2d(unsigned v, const std::string& path) {
    if (v > 1) unsupported(path, v);
    skip(v == 0 ? 12 : 24, path, "x, y, phi");
  }

  void pose_3d(unsigned v, const std::string& path) {
    // Version 0 held a float matrix object (MRPT before 0.9); not read.
    if (v < 1 || v > 3) unsupported(path, v);
    if (v == 1) object(path + ".HM", {Class::MatrixD}, 4, 4);
    if (v == 2) skip(56, path, "x, y, z, quaternion");
    if (v == 3) skip(96, path, "x, y, z, rotation");
  }

  void pose_pdf_gaussian(unsigned v, const std::string& path) {
    if (v < 1 || v > 2) unsupported(path, v);
    object(path + ".mean", {Class::Pose2D});
    skip(v == 1 ? 24 : 48, path, "covariance");
  }

  void pose_3d_pdf_gaussian(unsigned v, const std::string& path) {
    if (v != 1) unsupported(path, v);
    object(path + ".mean", {Class::Pose3D});
    skip(21 * 8, path, "covariance");
  }

  void matrix(unsigned v, const std::string& path, unsigned matrix_rows, unsigned matrix_cols) {
    if (v != 0) unsupported(path, v);
    const std::uint32_t rows = pod<std::uint32_t>(path, "rows");
    const std::uint32_t cols = pod<std::uint32_t>(path, "cols");
    // MRPT asserts the size after allocating it; a fixed-size field has one right size.
    if (rows != matrix_rows || cols != matrix_cols)
      throw RecordProblem(path, "a " + std::to_string(matrix_rows) + "x" + std::to_string(matrix_cols) +
                                    " matrix expected, got " + std::to_string(rows) + "x" + std::to_string(cols));
    skip(8 * std::size_t{rows} * cols, path, "matrix entries");
  }

  // Appends n bytes of input to the record, in chunks, so a count the input does not back
  // costs at most one chunk before the end of the input shows.
  void need(std::size_t n, const std::string& path, const char* what) {
    if (n > kMaxRecordBytes - std::min(out_.size(), kMaxRecordBytes))
      throw RecordProblem(path, std::string(what) + ": " + std::to_string(n) + " more bytes would exceed the " +
                                    std::to_string(kMaxRecordBytes >> 20) + " MiB a record may hold");
    while (n > 0) {
      const std::size_t chunk = std::min(n, kReadChunk);
      const std::size_t old = out_.size();
      out_.resize(old + chunk);
      std::size_t got = 0;
      while (got < chunk) {
        const std::size_t r = read_(out_.data() + old + got, chunk - got);
        if (r == 0) break;
        got += r;
      }
      if (got < chunk) {
        out_.resize(old + got);
        throw RecordProblem(path, std::string("truncated: the input ends inside ") + what, true);
      }
      n -= chunk;
    }
  }
  void skip(std::size_t n, const std::string& path, const char* what) { need(n, path, what); }

  template <typename T>
  T pod(const std::string& path, const char* what) {
    need(sizeof(T), path, what);
    T value;
    std::memcpy(&value, out_.data() + out_.size() - sizeof(T), sizeof(T));
    return value;  // little-endian, as MRPT writes on every platform we build for
  }

  // MRPT reads a bool as one byte into a C++ bool: anything but 0 or 1 is undefined behaviour.
  bool boolean(const std::string& field) {
    const std::uint8_t b = pod<std::uint8_t>(field, "flag");
    if (b > 1) throw RecordProblem(field, "a flag must be 0 or 1, got " + std::to_string(b));
    return b == 1;
  }

  // A flag whose value the reader ignores: any byte, rewritten in the record as 0 or 1 so that
  // MRPT never reads another value into a bool.
  bool legacy_flag(const std::string& field) {
    const std::uint8_t b = pod<std::uint8_t>(field, "flag");
    out_.back() = b != 0 ? 1 : 0;
    return b != 0;
  }

  // CObservation2DRangeScan versions 6 and 7 (MRPT 1.x and 2.x; earlier ones carry a float
  // matrix object MRPT 2 no longer knows): aperture, rightToLeft, maxRange, sensorPose, the
  // ranges and their validity, stdError, timestamp, beamAperture, sensorLabel, deltaPitch and
  // from version 7 the intensities.
  void range_scan_2d(unsigned v, const std::string& path) {
    if (v < 6 || v > 7) unsupported(path, v);
    skip(4, path, "aperture");
    boolean(path + ".rightToLeft");
    skip(4, path, "maxRange");
    object(path + ".sensorPose", {Class::Pose3D});
    const std::uint32_t n = count(path + ".scan", UINT32_MAX, 5);
    skip(4 * std::size_t{n}, path, "ranges");
    skip(n, path, "validRange");
    skip(4 + 8 + 4, path, "stdError, timestamp, beamAperture");
    string(path + ".sensorLabel");
    skip(8, path, "deltaPitch");
    if (v >= 7 && boolean(path + ".hasIntensity")) {
      if (std::size_t{n} * 4 > kMaxRecordBytes - std::min(out_.size(), kMaxRecordBytes))
        throw RecordProblem(path + ".intensity", "the intensities would exceed what a record may hold");
      skip(4 * std::size_t{n}, path, "intensity");
    }
  }

  // An element count; each element takes at least `element_bytes` of input, so the count must
  // fit in what a record may still hold (checked before MRPT would resize to it).
  std::uint32_t count(const std::string& field, std::uint32_t maximum, std::size_t element_bytes = 1) {
    const std::uint32_t n = pod<std::uint32_t>(field, "element count");
    if (n > maximum)
      throw RecordProblem(field, "count " + std::to_string(n) + " above the maximum " + std::to_string(maximum));
    const std::size_t room = kMaxRecordBytes - std::min(out_.size(), kMaxRecordBytes);
    if (std::size_t{n} * element_bytes > room)
      throw RecordProblem(field, "count " + std::to_string(n) + " needs " +
                                     std::to_string(std::size_t{n} * element_bytes) + " bytes, more than the " +
                                     std::to_string(room) + " a record may still hold");
    return n;
  }

  void string(const std::string& field) {
    const std::uint32_t n = count(field, kMaxLabelBytes);
    skip(n, field, "text");
  }

  const ByteReader& read_;
  std::vector<unsigned char>& out_;
};

}  // namespace

const std::vector<std::string>& accepted_record_classes() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (Class c : kTopLevel) out.push_back(info(c).name);
    return out;
  }();
  return names;
}

bool read_checked_record(const ByteReader& read, std::vector<unsigned char>& record) {
  record.clear();
  unsigned char first = 0;
  if (read(&first, 1) == 0) return false;
  // The first byte is read here to tell a clean end from a short record; give it back.
  std::size_t given = 0;
  const ByteReader replay = [&](void* buffer, std::size_t n) -> std::size_t {
    if (n == 0) return 0;
    if (given == 0) {
      given = 1;
      *static_cast<unsigned char*>(buffer) = first;
      return 1 + (n > 1 ? read(static_cast<unsigned char*>(buffer) + 1, n - 1) : 0);
    }
    return read(buffer, n);
  };
  Walker(replay, record).object("", kTopLevel);
  return true;
}

std::string record_class_name(std::span<const unsigned char> bytes, const std::string& path) {
  if (bytes.empty()) throw RecordProblem(path, "truncated: the input ends before the object header", true);
  const unsigned length = class_name_length(bytes[0], path);
  if (bytes.size() < 1 + std::size_t{length})
    throw RecordProblem(path, "truncated: the input ends inside the class name", true);
  std::string name(reinterpret_cast<const char*>(bytes.data() + 1), length);
  require_identifier(name, path);
  const std::size_t colon = name.rfind(':');
  return colon == std::string::npos ? name : name.substr(colon + 1);
}

}  // namespace relslam::eval
