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
  // The point-cloud reader's classes (read_checked_cloud_record).
  RangeScan3D,
  VelodyneScan,
  PointCloud,
  Image,
  Camera,
  SimplePointsMap,
  PointsMapXYZI,
  ColouredPointsMap,
  MapGenericParams,
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
    ClassInfo{Class::RangeScan3D, "CObservation3DRangeScan", "mrpt::obs::"},
    ClassInfo{Class::VelodyneScan, "CObservationVelodyneScan", "mrpt::obs::"},
    ClassInfo{Class::PointCloud, "CObservationPointCloud", "mrpt::obs::"},
    ClassInfo{Class::Image, "CImage", "mrpt::img::"},
    ClassInfo{Class::Camera, "TCamera", "mrpt::img::"},
    ClassInfo{Class::SimplePointsMap, "CSimplePointsMap", "mrpt::maps::"},
    ClassInfo{Class::PointsMapXYZI, "CPointsMapXYZI", "mrpt::maps::"},
    ClassInfo{Class::ColouredPointsMap, "CColouredPointsMap", "mrpt::maps::"},
    ClassInfo{Class::MapGenericParams, "TMapGenericParams", "mrpt::maps::"},
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
constexpr std::initializer_list<Class> kCloudTopLevel = {Class::ActionCollection, Class::SensoryFrame, Class::RangeScan3D,
                                                         Class::VelodyneScan, Class::PointCloud};
// A sensory frame of a point-cloud rawlog: the clouds and the planar reader's observations.
constexpr std::initializer_list<Class> kCloudInFrame = {Class::RangeScan3D, Class::VelodyneScan, Class::PointCloud,
                                                        Class::BearingRange, Class::RangeScan2D, Class::Odometry};
constexpr std::initializer_list<Class> kPointMaps = {Class::SimplePointsMap, Class::PointsMapXYZI,
                                                     Class::ColouredPointsMap};
constexpr auto kMaxSide = static_cast<std::uint32_t>(kMaxWalkedImageSide);

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
  // `max_bytes`: what the record may hold; `clouds`: sensory frames may hold point clouds.
  Walker(const ByteReader& read, std::vector<unsigned char>& out, std::size_t max_bytes = kMaxRecordBytes,
         bool clouds = false)
      : read_(read), out_(out), max_bytes_(max_bytes), clouds_(clouds) {}

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
      case Class::RangeScan3D: return range_scan_3d(v, path);
      case Class::VelodyneScan: return velodyne_scan(v, path);
      case Class::PointCloud: return point_cloud(v, path);
      case Class::Image: return image(v, path);
      case Class::Camera: return camera(v, path);
      case Class::SimplePointsMap:
      case Class::PointsMapXYZI:
      case Class::ColouredPointsMap: return points_map(c, v, path);
      case Class::MapGenericParams: return map_generic_params(v, path);
    }
  }

  void sensory_frame(unsigned v, const std::string& path) {
    if (v > 2) unsupported(path, v);
    if (v < 2) skip(4, path, "ID");
    if (v == 0) skip(8, path, "timestamp");
    const std::uint32_t n = count(path + ".observations", kMaxObjectsPerContainer);
    for (std::uint32_t i = 0; i < n; ++i)
      object(path + ".observations[" + std::to_string(i) + "]", clouds_ ? kCloudInFrame : kInFrame);
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

  // CObservation3DRangeScan versions 9 and 10 (MRPT 1.9 on; earlier ones keep the range image as
  // a float matrix object): maxRange, sensorPose, the 3D points, the range image, the intensity
  // and confidence images, the cameras, stdError, timestamp, sensorLabel, the external-storage
  // fields, range_is_depth, the intensity channel, pixel labels (not read) and from version 10
  // further range layers.
  void range_scan_3d(unsigned v, const std::string& path) {
    if (v < 9 || v > 10) unsupported(path, v);
    skip(4, path, "maxRange");
    object(path + ".sensorPose", {Class::Pose3D});
    if (boolean(path + ".hasPoints3D")) {
      const std::uint32_t n = count(path + ".points3D", UINT32_MAX, 16);  // x, y, z; two pixel indices
      skip(16 * std::size_t{n}, path + ".points3D", "x, y, z and pixel indices");
    }
    const bool range_image = boolean(path + ".hasRangeImage");
    skip(4, path, "rangeUnits");
    if (range_image) range_image_field(path + ".rangeImage");
    dropped_image(path + ".hasIntensityImage", path + ".intensityImage");
    dropped_image(path + ".hasConfidenceImage", path + ".confidenceImage");
    object(path + ".cameraParams", {Class::Camera});
    object(path + ".cameraParamsIntensity", {Class::Camera});
    object(path + ".relativePoseIntensityWRTDepth", {Class::Pose3D});
    skip(4 + 8, path, "stdError, timestamp");
    string(path + ".sensorLabel");
    for (const char* storage : {".points3D_external", ".rangeImage_external"}) {
      boolean(path + storage + "_stored");
      string(path + storage + "_file");
    }
    boolean(path + ".range_is_depth");
    const auto channel = pod<std::int8_t>(path, "intensityImageChannel");
    if (channel != 0 && channel != 1)
      throw RecordProblem(path + ".intensityImageChannel",
                          "must be 0 (visible) or 1 (infrared), got " + std::to_string(channel));
    if (boolean(path + ".pixelLabels")) throw RecordProblem(path + ".pixelLabels", "pixel labels are not read");
    if (v < 10) return;
    const auto layers = pod<std::uint8_t>(path, "rangeImageOtherLayers");
    for (unsigned i = 0; i < layers; ++i) {
      const std::string layer = path + ".rangeImageOtherLayers[" + std::to_string(i) + "]";
      string(layer + ".name");
      range_image_field(layer);
    }
  }

  // A range image: rows, cols, then 16-bit pixels; MRPT sizes it before reading a pixel.
  void range_image_field(const std::string& field) {
    const auto rows = pod<std::uint32_t>(field, "rows");
    const auto cols = pod<std::uint32_t>(field, "cols");
    if (rows > kMaxSide || cols > kMaxSide)
      throw RecordProblem(field, std::to_string(cols) + "x" + std::to_string(rows) + " pixels, beyond " +
                                     std::to_string(kMaxWalkedImageSide) + " either way");
    skip(2 * std::size_t{rows} * cols, field, "pixels");
  }

  // An image the reader does not use, after its flag: walked, then cut from the record and its
  // flag set to 0, so MRPT never decodes it (a JPEG's header may claim any size).
  void dropped_image(const std::string& flag, const std::string& field) {
    if (!boolean(flag)) return;
    const std::size_t at = out_.size();
    object(field, {Class::Image});
    out_.resize(at);
    out_.back() = 0;
  }

  // CImage versions 6 to 9 (MRPT 1.x and 2.x): external file name, or a grey image's raw bytes
  // (ZIP is not read: MRPT 2 no longer can), or a colour image as JPEG or raw RGB.
  void image(unsigned v, const std::string& path) {
    if (v < 6 || v > 9) unsupported(path, v);
    if (boolean(path + ".imgIsExternalStorage")) return string(path + ".externalFile");
    if (pod<std::uint8_t>(path, "hasColor") == 0) {
      skip(12, path, "width, height, origin");
      const auto size = pod<std::int32_t>(path, "imageSize");
      if (v >= 9) skip(4, path, "depth");
      if (boolean(path + ".imageIsZIP")) throw RecordProblem(path, "a ZIP-compressed image is not read");
      if (size < 0) throw RecordProblem(path + ".imageSize", "negative: " + std::to_string(size));
      return skip(static_cast<std::size_t>(size), path, "pixels");
    }
    std::int32_t width = 1, height = 1;
    if (v >= 7) {
      width = pod<std::int32_t>(path, "width");
      height = pod<std::int32_t>(path, "height");
    }
    if (width >= 1 && height >= 1) return skip(count(path + ".jpeg", UINT32_MAX), path, "JPEG bytes");
    if (width < -kMaxWalkedImageSide || height < -kMaxWalkedImageSide)
      throw RecordProblem(path, "a raw image beyond " + std::to_string(kMaxWalkedImageSide) + " pixels either way");
    if (width < 0 && height < 0) skip(3 * std::size_t(-width) * std::size_t(-height), path, "RGB pixels");
  }

  // TCamera versions 4 to 6: focal length, 8 distortion coefficients, fx, fy, cx, cy, rows,
  // cols, from 5 a name, from 6 the distortion model.
  void camera(unsigned v, const std::string& path) {
    if (v < 4 || v > 6) unsupported(path, v);
    skip(8 + 64 + 32 + 8, path, "focal length, distortion, intrinsics, size");
    if (v >= 5) string(path + ".cameraName");
    if (v < 6) return;
    const auto model = pod<std::uint8_t>(path, "distortion");
    if (model > 2)
      throw RecordProblem(path + ".distortion",
                          "must be 0 (none), 1 (plumb bob) or 2 (Kannala-Brandt), got " + std::to_string(model));
  }

  // CObservationVelodyneScan versions 0 to 2: timestamp, sensorLabel, min and max range,
  // sensorPose, raw packets, calibration, the decoded cloud and from version 2 its per-point
  // times, azimuths, laser ids and points per laser.
  void velodyne_scan(unsigned v, const std::string& path) {
    if (v > 2) unsupported(path, v);
    skip(8, path, "timestamp");
    string(path + ".sensorLabel");
    skip(16, path, "minRange, maxRange");
    object(path + ".sensorPose", {Class::Pose3D});
    constexpr std::size_t kPacketBytes = 1206, kCalibrationBytes = 72;  // MRPT's packed structs
    skip(kPacketBytes * count(path + ".scan_packets", UINT32_MAX, kPacketBytes), path, "scan_packets");
    skip(kCalibrationBytes * count(path + ".calibration", UINT32_MAX, kCalibrationBytes), path, "calibration");
    for (const char* axis : {".point_cloud.x", ".point_cloud.y", ".point_cloud.z"}) plain_vector(path + axis, 4);
    plain_vector(path + ".point_cloud.intensity", 1);
    if (v >= 1) boolean(path + ".has_satellite_timestamp");
    if (v < 2) return;
    type_names(path + ".point_cloud.timestamp", "uint64_t");
    plain_vector(path + ".point_cloud.timestamp", 8);
    plain_vector(path + ".point_cloud.azimuth", 4);
    plain_vector(path + ".point_cloud.laser_id", 2);
    type_names(path + ".point_cloud.pointsForLaserID", "std::vector<uint64_t>");
    const std::string lasers = path + ".point_cloud.pointsForLaserID";
    const std::uint32_t n = count(lasers, UINT32_MAX, 4);
    for (std::uint32_t i = 0; i < n; ++i) plain_vector(lasers + "[" + std::to_string(i) + "]", 8);
  }

  // CObservationPointCloud version 0: sensorLabel, timestamp, sensorPose, the storage flag and a
  // point map.
  void point_cloud(unsigned v, const std::string& path) {
    if (v != 0) unsupported(path, v);
    string(path + ".sensorLabel");
    skip(8, path, "timestamp");
    object(path + ".sensorPose", {Class::Pose3D});
    if (pod<std::uint8_t>(path, "externally_stored") != 0)
      throw RecordProblem(path + ".pointcloud", "stored in an external file beside the rawlog: not read");
    object(path + ".pointcloud", kPointMaps);
  }

  // The point maps MRPT 2 writes: CSimplePointsMap 9-10, CColouredPointsMap 9, CPointsMapXYZI 0.
  void points_map(Class c, unsigned v, const std::string& path) {
    const bool simple = c == Class::SimplePointsMap, coloured = c == Class::ColouredPointsMap;
    if ((simple && (v < 9 || v > 10)) || (coloured && v != 9) || (c == Class::PointsMapXYZI && v != 0))
      unsupported(path, v);
    const std::size_t per_point = c == Class::PointsMapXYZI ? 16 : 12;
    skip(per_point * count(path + ".points", UINT32_MAX, per_point), path, "points");
    if (coloured)
      for (const char* channel : {".color_R", ".color_G", ".color_B"}) plain_vector(path + channel, 4);
    if (c != Class::PointsMapXYZI) object(path + ".genericMapParams", {Class::MapGenericParams});
    options_block(path + ".insertionOptions", 4 + 5 + 4 + 4 + 1);  // floats and flags of version 0
    options_block(path + ".likelihoodOptions", 8 + 8 + 4);
    if (simple && v >= 10) options_block(path + ".renderOptions", 4 + 16 + 1);
  }

  void map_generic_params(unsigned v, const std::string& path) {
    if (v != 0) unsupported(path, v);
    for (const char* flag : {".enableSaveAs3DObject", ".enableObservationLikelihood", ".enableObservationInsertion"})
      boolean(path + flag);
  }

  // A point map's options: a version byte (0, the only one) and `bytes` of fields.
  void options_block(const std::string& field, std::size_t bytes) {
    const auto version = pod<std::int8_t>(field, "version");
    if (version != 0) throw RecordProblem(field, "options version " + std::to_string(version) + " is not read");
    skip(bytes, field, "options");
  }

  // MRPT's plain vector: a count, then its elements of `bytes` each.
  void plain_vector(const std::string& field, std::size_t bytes) {
    skip(bytes * count(field, UINT32_MAX, bytes), field, "elements");
  }

  // The two type names MRPT writes before a vector of other types: "std::vector" and the element.
  void type_names(const std::string& field, const std::string& element) {
    for (const std::string& expected : {std::string("std::vector"), element}) {
      const std::uint32_t n = count(field, kMaxLabelBytes);
      skip(n, field, "type name");
      if (std::string(reinterpret_cast<const char*>(out_.data() + out_.size() - n), n) != expected)
        throw RecordProblem(field, "the type name must be " + expected);
    }
  }

  // Appends n bytes of input to the record, in chunks, so a count the input does not back
  // costs at most one chunk before the end of the input shows.
  void need(std::size_t n, const std::string& path, const char* what) {
    if (n > max_bytes_ - std::min(out_.size(), max_bytes_))
      throw RecordProblem(path, std::string(what) + ": " + std::to_string(n) + " more bytes would exceed the " +
                                    std::to_string(max_bytes_ >> 20) + " MiB a record may hold");
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
      if (std::size_t{n} * 4 > max_bytes_ - std::min(out_.size(), max_bytes_))
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
    const std::size_t room = max_bytes_ - std::min(out_.size(), max_bytes_);
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
  std::size_t max_bytes_;
  bool clouds_;
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

namespace {

bool read_record(const ByteReader& read, std::vector<unsigned char>& record, std::initializer_list<Class> top_level,
                 std::size_t max_bytes, bool clouds) {
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
  Walker(replay, record, max_bytes, clouds).object("", top_level);
  return true;
}

}  // namespace

bool read_checked_record(const ByteReader& read, std::vector<unsigned char>& record) {
  return read_record(read, record, kTopLevel, kMaxRecordBytes, false);
}

bool read_checked_cloud_record(const ByteReader& read, std::vector<unsigned char>& record, std::size_t max_bytes) {
  return read_record(read, record, kCloudTopLevel, max_bytes, true);
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
