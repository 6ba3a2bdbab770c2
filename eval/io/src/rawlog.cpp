#include "relslam/eval/io/rawlog.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/mrpt_observation.hpp"
#include "relslam/eval/io/range_bearing.hpp"

#include <mrpt/core/Clock.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CActionRobotMovement3D.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/poses/CPose3DQuat.h>

#include <mrpt/serialization/CArchive.h>
#include <Eigen/Geometry>

#include <array>
#include <cctype>
#include <cmath>
#include <fstream>

namespace relslam::eval {
namespace {

using mrpt::obs::CActionCollection;
using mrpt::obs::CObservationBearingRange;
using mrpt::obs::CSensoryFrame;

Rigid3 rigid_of(const mrpt::poses::CPose3D& pose) {
  Rigid3 r;
  r.rotation = pose.getRotationMatrix().asEigen();
  r.translation = {pose.x(), pose.y(), pose.z()};
  return r;
}

// A frame's odometry as MRPT's odometry action, with MRPT's default Gaussian motion model for
// its uncertainty: planar motions (about our +y, in our x-z plane) as a 2D action, which
// both the 2D and 6D filters read, anything else as a 3D one.
CActionCollection odometry_actions(const ObservationFrame& frame) {
  CActionCollection actions;
  if (!frame.odometry) return actions;
  const Rigid3 m = mrpt_axes_from_robot(*frame.odometry);
  const bool planar = std::abs(m.translation.z()) < 1e-12 && std::abs(m.rotation(2, 2) - 1.0) < 1e-12;
  if (planar) {
    mrpt::obs::CActionRobotMovement2D move;
    const Pose2 p = planar_from_robot_pose(*frame.odometry);
    move.computeFromOdometry(mrpt::poses::CPose2D(p.x, p.y, p.heading),
                             mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
    actions.insert(move);
  } else {
    mrpt::obs::CActionRobotMovement3D move;
    const Eigen::Quaterniond q(m.rotation);
    move.computeFromOdometry(
        mrpt::poses::CPose3D(mrpt::poses::CPose3DQuat(m.translation.x(), m.translation.y(), m.translation.z(),
                                                      mrpt::math::CQuaternionDouble(q.w(), q.x(), q.y(), q.z()))),
        mrpt::obs::CActionRobotMovement3D::TMotionModelOptions());
    actions.insert(move);
  }
  return actions;
}

std::optional<Rigid3> odometry_of(const CActionCollection& actions) {
  if (auto a3 = actions.getActionByClass<mrpt::obs::CActionRobotMovement3D>()) return rigid_of(a3->poseChange.mean);
  if (auto a2 = actions.getActionByClass<mrpt::obs::CActionRobotMovement2D>())
    return rigid_of(mrpt::poses::CPose3D(a2->poseChange->getMeanVal()));
  return std::nullopt;
}

// A NaN or infinite measurement would poison every estimate downstream; reject it here,
// naming the record and the measurement, instead of producing silently wrong numbers.
RangeBearingSensor sensor_of(const CObservationBearingRange& obs) {
  RangeBearingSensor s;
  s.min_range = obs.minSensorDistance;
  s.max_range = obs.maxSensorDistance;
  s.field_of_view_yaw_rad = obs.fieldOfView_yaw;
  s.field_of_view_pitch_rad = obs.fieldOfView_pitch;
  s.std_range = obs.sensor_std_range;
  s.std_yaw_rad = obs.sensor_std_yaw;
  s.std_pitch_rad = obs.sensor_std_pitch;
  return s;
}

RawlogFrame frame_of(const CObservationBearingRange& obs, int index, const std::string& file, int record) {
  RawlogFrame frame;
  frame.index = index;
  frame.timestamp_s = mrpt::Clock::toDouble(obs.timestamp);
  frame.robot_T_sensor = rigid_of(obs.sensorLocationOnRobot);
  frame.measurements.reserve(obs.sensedData.size());
  for (std::size_t i = 0; i < obs.sensedData.size(); ++i) {
    const auto& m = obs.sensedData[i];
    const std::string field = "sensedData[" + std::to_string(i) + "]";
    if (!std::isfinite(m.range) || !std::isfinite(m.yaw) || !std::isfinite(m.pitch))
      throw InputError(file, record, field,
                       "range/yaw/pitch must be finite, got " + std::to_string(m.range) + "/" + std::to_string(m.yaw) +
                           "/" + std::to_string(m.pitch));
    if (m.range < 0) throw InputError(file, record, field, "negative range " + std::to_string(m.range));
    frame.measurements.push_back({m.range, m.yaw, m.pitch, m.landmarkID});
  }
  return frame;
}

// MRPT deserialises whatever bytes it is given; a text or image file can make it allocate
// gigabytes for a "class name". So check the first record's header ourselves: a serialised
// object starts with 0x80 | length, then that many identifier characters naming a class.
void require_mrpt_header(const std::filesystem::path& path) {
  mrpt::io::CFileGZInputStream in;
  if (!in.open(path.string())) throw InputError(path.string(), 0, "", "cannot open file");
  std::array<unsigned char, 128> head{};
  const std::size_t n = in.Read(head.data(), head.size());
  if (n == 0) throw InputError(path.string(), 0, "", "empty file: not an MRPT rawlog");
  const unsigned length = head[0] & 0x7F;
  bool ok = (head[0] & 0x80) != 0 && length >= 2 && 1 + length <= n;
  for (unsigned i = 0; ok && i < length; ++i)
    ok = std::isalnum(head[1 + i]) || head[1 + i] == '_' || head[1 + i] == ':';
  // Every MRPT serialisable class is called C..., with its namespace in MRPT 2 ("mrpt::obs::C...").
  const std::string class_name(reinterpret_cast<const char*>(head.data()) + 1, ok ? length : 0);
  const std::size_t colons = class_name.rfind("::");
  ok = ok && class_name[colons == std::string::npos ? 0 : colons + 2] == 'C';
  if (!ok) throw InputError(path.string(), 1, "", "not an MRPT rawlog (the first record has no MRPT object header)");
}

// MRPT's exception text is a banner, a "Message:" line and a call stack; keep the message.
std::string mrpt_message(const std::string& what) {
  const std::size_t start = what.find("Message:");
  std::string line = start == std::string::npos ? what : what.substr(start + 8);
  line = line.substr(0, line.find('\n'));
  const std::size_t first = line.find_first_not_of(' ');
  return first == std::string::npos ? what.substr(0, what.find('\n')) : line.substr(first);
}

}  // namespace

Rawlog read_rawlog(const std::filesystem::path& path) {
  const std::string name = path.string();
  if (!std::filesystem::exists(path)) throw InputError(name, 0, "", "file not found");
  if (std::filesystem::is_directory(path)) throw InputError(name, 0, "", "is a directory, not a rawlog");
  require_mrpt_header(path);

  mrpt::io::CFileGZInputStream in;
  if (!in.open(name)) throw InputError(name, 0, "", "cannot open file");
  auto archive = mrpt::serialization::archiveFrom(in);

  Rawlog log;
  bool any_action = false, any_frame = false;
  std::optional<Rigid3> pending_odometry;                     // action waiting for its frame
  std::optional<mrpt::poses::CPose2D> last_odometry_reading;  // observation-only files
  for (int record = 1;; ++record) {
    const std::uint64_t before = in.getPosition();
    mrpt::serialization::CSerializable::Ptr object;
    try {
      object = archive.ReadObject();
    } catch (const mrpt::serialization::CExceptionEOF&) {
      if (in.getPosition() == before) break;  // clean end between records
      throw InputError(name, record, "", "truncated: the file ends inside record " + std::to_string(record));
    } catch (const std::exception& e) {
      // MRPT wraps a short read inside an object in a generic error; EOF tells them apart.
      if (in.checkEOF())
        throw InputError(name, record, "", "truncated: the file ends inside record " + std::to_string(record));
      throw InputError(name, record, "", "unreadable record (corrupt or not a rawlog): " + mrpt_message(e.what()));
    }
    log.records = record;
    if (auto actions = std::dynamic_pointer_cast<CActionCollection>(object)) {
      if (!any_action && !any_frame) log.sensory_frame_first = false;
      any_action = true;
      pending_odometry = odometry_of(*actions);
    } else if (auto sf = std::dynamic_pointer_cast<CSensoryFrame>(object)) {
      if (!any_action && !any_frame) log.sensory_frame_first = true;
      any_frame = true;
      auto obs = sf->getObservationByClass<CObservationBearingRange>();
      if (!obs) {
        log.skipped_observations += static_cast<int>(sf->size());
        continue;
      }
      log.skipped_observations += static_cast<int>(sf->size()) - 1;
      if (log.frames.empty()) log.sensor = sensor_of(*obs);
      RawlogFrame frame = frame_of(*obs, static_cast<int>(log.frames.size()), name, record);
      frame.odometry = pending_odometry;
      pending_odometry.reset();
      log.frames.push_back(std::move(frame));
    } else if (auto obs = std::dynamic_pointer_cast<CObservationBearingRange>(object)) {
      if (log.frames.empty()) log.sensor = sensor_of(*obs);
      log.format = Rawlog::Format::ObservationsOnly;
      RawlogFrame frame = frame_of(*obs, static_cast<int>(log.frames.size()), name, record);
      frame.odometry = pending_odometry;
      pending_odometry.reset();
      log.frames.push_back(std::move(frame));
    } else if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(object)) {
      log.format = Rawlog::Format::ObservationsOnly;
      // Absolute odometry readings: the increment since the previous reading is the motion.
      if (last_odometry_reading)
        pending_odometry = rigid_of(mrpt::poses::CPose3D(odo->odometry - *last_odometry_reading));
      last_odometry_reading = odo->odometry;
    } else if (std::dynamic_pointer_cast<mrpt::obs::CObservation>(object)) {
      log.format = Rawlog::Format::ObservationsOnly;
      ++log.skipped_observations;
    } else {
      throw InputError(
          name, record, "",
          std::string("unexpected object of class ") + object->GetRuntimeClass()->className + " in a rawlog");
    }
  }
  if (log.frames.empty())
    throw InputError(name, 0, "",
                     "no CObservationBearingRange in " + std::to_string(log.records) +
                         " records: nothing for a landmark SLAM algorithm to read");
  if (any_action && any_frame) log.format = Rawlog::Format::ActionsSensoryFrames;
  return log;
}

ObservationFrame observation_frame(const RawlogFrame& frame) {
  ObservationFrame out;
  out.iteration = frame.index;
  out.points.reserve(frame.measurements.size());
  for (const RawlogMeasurement& m : frame.measurements) {
    const Eigen::Vector3d p_sensor = point_of({m.range, m.yaw_rad, m.pitch_rad});
    out.points.push_back(robot_from_mrpt(frame.robot_T_sensor * p_sensor));
  }
  if (frame.odometry) out.odometry = robot_axes_from_mrpt(*frame.odometry);
  return out;
}

struct RawlogWriter::Impl {
  std::unique_ptr<mrpt::io::CStream> stream;
  // Each record is serialised into memory first and written with one call: MRPT's archive
  // issues one stream write per field, which is several times slower on a file stream.
  mrpt::io::CMemoryStream record;
  RangeBearingSensor sensor;
  std::string name;
};

RawlogWriter::RawlogWriter(const std::filesystem::path& path, const RangeBearingSensor& sensor, bool gzip)
    : impl_(std::make_unique<Impl>()) {
  impl_->sensor = sensor;
  impl_->name = path.string();
  if (gzip) {
    auto s = std::make_unique<mrpt::io::CFileGZOutputStream>();
    if (!s->open(impl_->name, 1)) throw std::runtime_error(impl_->name + ": cannot create file");
    impl_->stream = std::move(s);
  } else {
    auto s = std::make_unique<mrpt::io::CFileOutputStream>();
    if (!s->open(impl_->name, mrpt::io::OpenMode::TRUNCATE))
      throw std::runtime_error(impl_->name + ": cannot create file");
    impl_->stream = std::move(s);
  }
}

RawlogWriter::~RawlogWriter() = default;

void RawlogWriter::write(const ObservationFrame& frame, const std::vector<int>& landmark_ids, double timestamp_s) {
  if (!impl_->stream) throw std::logic_error(impl_->name + ": write after close");
  CSensoryFrame sf;
  sf.insert(bearing_range_observation(frame, landmark_ids, impl_->sensor, timestamp_s));
  // Action first: kf-slam then pairs step k with frame k. Empty without odometry.
  const CActionCollection actions = odometry_actions(frame);
  impl_->record.clear();
  auto archive = mrpt::serialization::archiveFrom(impl_->record);
  archive << actions << sf;
  const auto bytes = static_cast<std::size_t>(impl_->record.getPosition());  // bytes written since clear()
  if (impl_->stream->Write(impl_->record.getRawBufferData(), bytes) != bytes)
    throw std::runtime_error(impl_->name + ": write failed (disk full?)");
}

void RawlogWriter::close() { impl_->stream.reset(); }

}  // namespace relslam::eval
