#include "relslam/eval/io/rawlog.hpp"

#include "relslam/core/option_issue.hpp"
#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/mrpt_exception_message.hpp"
#include "relslam/eval/io/mrpt_observation.hpp"
#include "relslam/eval/io/range_bearing.hpp"

#include "mrpt_read_helpers.hpp"
#include "laser_scan_record.hpp"
#include "mrpt_record_check.hpp"
#include "rawlog_record_stream.hpp"

#include <mrpt/core/Clock.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CActionRobotMovement3D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/poses/CPose3DQuat.h>
#include <mrpt/system/os.h>

#include <mrpt/serialization/CArchive.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string_view>
#include <utility>

namespace relslam::eval {
namespace {

using mrpt::obs::CActionCollection;
using mrpt::obs::CObservationBearingRange;
using mrpt::obs::CSensoryFrame;

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

std::optional<Rigid3> odometry_of(const CActionCollection& actions, const std::string& file, int record) {
  std::optional<Rigid3> odometry;
  if (auto a3 = actions.getActionByClass<mrpt::obs::CActionRobotMovement3D>())
    odometry = rigid_of(a3->poseChange.mean);
  else if (auto a2 = actions.getActionByClass<mrpt::obs::CActionRobotMovement2D>())
    odometry = rigid_of(mrpt::poses::CPose3D(a2->poseChange->getMeanVal()));
  if (odometry) require_sane(*odometry, kMaxOdometryStep_m, file, record, "odometry");
  return odometry;
}

// What the sensor values must satisfy besides finiteness (rawlog.hpp states the ranges).
void check_sensor_sense(const RangeBearingSensor& s, const std::string& file, int record) {
  const auto fail = [&](const char* field, const std::string& problem, double value) {
    throw InputError(file, record, field, problem + ", got " + format_number(value));
  };
  if (!(s.field_of_view_yaw_rad > 0 && s.field_of_view_yaw_rad <= 2 * std::numbers::pi))
    fail("fieldOfView_yaw", "must be in (0, 2 pi]", s.field_of_view_yaw_rad);
  // 0 is a planar sensor (a 2D laser: our Victoria Park conversion writes it).
  if (!(s.field_of_view_pitch_rad >= 0 && s.field_of_view_pitch_rad <= 2 * std::numbers::pi))
    fail("fieldOfView_pitch", "must be in [0, 2 pi]", s.field_of_view_pitch_rad);
  if (s.min_range < 0) fail("minSensorDistance", "must be >= 0", s.min_range);
  if (s.max_range > kMaxSensorRange_m)
    fail("maxSensorDistance", "must be <= " + format_number(kMaxSensorRange_m) + " m", s.max_range);
  if (s.max_range != 0 && s.max_range <= s.min_range)
    fail("maxSensorDistance",
         "must be above minSensorDistance (" + format_number(s.min_range) + "), or 0 with it for no range given",
         s.max_range);
  if (s.max_range == 0 && s.min_range != 0)
    fail("maxSensorDistance", "must be above minSensorDistance (" + format_number(s.min_range) + ")", s.max_range);
  const std::pair<const char*, double> deviations[] = {
      {"sensor_std_range", s.std_range}, {"sensor_std_yaw", s.std_yaw_rad}, {"sensor_std_pitch", s.std_pitch_rad}};
  for (const auto& [field, value] : deviations)
    if (value < 0) fail(field, "must be >= 0", value);
}

// What the action states about its own uncertainty, for the EKFs' odometry noise; nothing for
// an action without a (finite, positive) covariance.
std::optional<OdometryStd> odometry_std_of(const CActionCollection& actions) {
  double xyz = 0, angle = 0;
  if (auto a3 = actions.getActionByClass<mrpt::obs::CActionRobotMovement3D>()) {
    const auto& c = a3->poseChange.cov;
    xyz = std::max({c(0, 0), c(1, 1), c(2, 2)});
    angle = std::max({c(3, 3), c(4, 4), c(5, 5)});
  } else if (auto a2 = actions.getActionByClass<mrpt::obs::CActionRobotMovement2D>(); a2 && a2->poseChange) {
    mrpt::math::CMatrixDouble33 c;
    a2->poseChange->getCovariance(c);
    xyz = std::max(c(0, 0), c(1, 1));
    angle = c(2, 2);
  }
  if (!(xyz > 0 && angle > 0 && std::isfinite(xyz) && std::isfinite(angle))) return std::nullopt;
  return OdometryStd{std::sqrt(xyz), std::sqrt(angle)};
}

// A NaN or infinite value would poison every estimate downstream; reject it here, naming the
// record and the field, instead of producing silently wrong numbers. Every observation is
// checked, though only the first one's sensor is kept.
RangeBearingSensor sensor_of(const CObservationBearingRange& obs, const std::string& file, int record) {
  RangeBearingSensor s;
  s.min_range = obs.minSensorDistance;
  s.max_range = obs.maxSensorDistance;
  s.field_of_view_yaw_rad = obs.fieldOfView_yaw;
  s.field_of_view_pitch_rad = obs.fieldOfView_pitch;
  s.std_range = obs.sensor_std_range;
  s.std_yaw_rad = obs.sensor_std_yaw;
  s.std_pitch_rad = obs.sensor_std_pitch;
  const std::pair<const char*, double> values[] = {{"minSensorDistance", s.min_range},
                                                   {"maxSensorDistance", s.max_range},
                                                   {"fieldOfView_yaw", s.field_of_view_yaw_rad},
                                                   {"fieldOfView_pitch", s.field_of_view_pitch_rad},
                                                   {"sensor_std_range", s.std_range},
                                                   {"sensor_std_yaw", s.std_yaw_rad},
                                                   {"sensor_std_pitch", s.std_pitch_rad}};
  for (const auto& [field, value] : values)
    if (!std::isfinite(value)) throw InputError(file, record, field, "must be finite, got " + std::to_string(value));
  check_sensor_sense(s, file, record);
  return s;
}

// A reading within the observation's range (with kRangeTolerance for noise) and angles within
// a turn; `field` names it.
void check_reading(const CObservationBearingRange::TMeasurement& m, const CObservationBearingRange& obs,
                   const std::string& file, int record, const std::string& field) {
  if (!std::isfinite(m.range) || !std::isfinite(m.yaw) || !std::isfinite(m.pitch))
    throw InputError(file, record, field,
                     "range/yaw/pitch must be finite, got " + std::to_string(m.range) + "/" + std::to_string(m.yaw) +
                         "/" + std::to_string(m.pitch));
  if (m.range < 0) throw InputError(file, record, field, "negative range " + std::to_string(m.range));
  const double limit = (1.0 + kRangeTolerance) * obs.maxSensorDistance;
  if (obs.maxSensorDistance > 0 && m.range > limit)
    throw InputError(file, record, field,
                     "range " + format_number(m.range) + " beyond the observation's maxSensorDistance " +
                         format_number(obs.maxSensorDistance) + " (at most " + format_number(limit) + ")");
  if (std::abs(m.yaw) > 2 * std::numbers::pi || std::abs(m.pitch) > 2 * std::numbers::pi)
    throw InputError(file, record, field,
                     "yaw/pitch must be within +-2 pi, got " + format_number(m.yaw) + "/" + format_number(m.pitch));
}

RawlogFrame frame_of(const CObservationBearingRange& obs, int index, const std::string& file, int record) {
  RawlogFrame frame;
  frame.index = index;
  frame.timestamp_s = mrpt::Clock::toDouble(obs.timestamp);
  frame.robot_T_sensor = rigid_of(obs.sensorLocationOnRobot);
  require_sane(frame.robot_T_sensor, kMaxSensorOffset_m, file, record, "sensorLocationOnRobot");
  sensor_of(obs, file, record);
  frame.measurements.reserve(obs.sensedData.size());
  for (std::size_t i = 0; i < obs.sensedData.size(); ++i) {
    const auto& m = obs.sensedData[i];
    check_reading(m, obs, file, record, "sensedData[" + std::to_string(i) + "]");
    frame.measurements.push_back({m.range, m.yaw, m.pitch, m.landmarkID});
  }
  return frame;
}

// Odometry in MRPT's robot axes as a planar increment (x, y, yaw -> x, z, heading), for scans.
PlanarPose planar_odometry(const Rigid3& m) {
  return PlanarPose::from(m.translation.x(), m.translation.y(), std::atan2(m.rotation(1, 0), m.rotation(0, 0)));
}

// A laser scan read from `record`, paired with the odometry waiting for it.
void add_scan(Rawlog& log, const mrpt::obs::CObservation2DRangeScan& obs, const std::optional<Rigid3>& odometry,
              const std::string& file, int record) {
  RawlogScan scan;
  scan.index = static_cast<int>(log.scans.size());
  const LaserScanLimits limits{kMaxSensorRange_m, kRangeTolerance, kMaxSensorOffset_m, kMaxScanTilt_rad};
  scan.scan = laser_scan_of(obs, limits, file, record);
  if (odometry) scan.odometry = planar_odometry(*odometry);
  log.scans.push_back(std::move(scan));
}

// A CObservationOdometry reading, and the increment since the previous one that becomes the
// next frame's odometry; both within the bounds rawlog.hpp states.
std::optional<Rigid3> odometry_increment(const mrpt::obs::CObservationOdometry& odo,
                                         const std::optional<mrpt::poses::CPose2D>& last, const std::string& file,
                                         int record) {
  require_sane(rigid_of(mrpt::poses::CPose3D(odo.odometry)), kMaxOdometryReading_m, file, record,
               "CObservationOdometry.odometry");
  if (!last) return std::nullopt;
  const Rigid3 increment = rigid_of(mrpt::poses::CPose3D(odo.odometry - *last));
  require_sane(increment, kMaxOdometryStep_m, file, record, "CObservationOdometry.odometry (since the last reading)");
  return increment;
}


// The next record's bytes, checked by mrpt_record_check.hpp; false at a clean end between
// records. Each RecordProblem becomes an InputError naming the file and the record.
bool next_record(const ByteReader& read, std::vector<unsigned char>& bytes, const std::string& name, int record) {
  try {
    if (read_checked_record(read, bytes)) return true;
    if (record == 1) throw InputError(name, 0, "", "empty file: not an MRPT rawlog");
    return false;
  } catch (const RecordProblem& p) {
    if (p.truncated())
      throw InputError(name, record, p.field(),
                       "truncated: the file ends inside record " + std::to_string(record) + " (" + p.what() + ")");
    if (record == 1 && p.field().empty())
      throw InputError(name, record, "", std::string("not an MRPT rawlog (") + p.what() + ")");
    throw InputError(name, record, p.field(), p.what());
  }
}

// Every record goes through our own bounds first (mrpt_record_check.hpp); MRPT then decodes
// exactly the bytes that passed, from memory. `budget` bounds the decoded bytes of all records.
Rawlog read_records(mrpt::io::CStream& in, const std::string& name, std::size_t budget) {
  const ByteReader read = [&in](void* buffer, std::size_t n) { return in.Read(buffer, n); };
  std::vector<unsigned char> bytes;
  Rawlog log;
  bool any_action = false, any_frame = false;
  std::optional<Rigid3> pending_odometry;                     // action waiting for its frame
  std::optional<mrpt::poses::CPose2D> last_odometry_reading;  // observation-only files
  std::size_t decoded = 0;
  for (int record = 1;; ++record) {
    if (!next_record(read, bytes, name, record)) break;
    decoded += bytes.size();
    if (decoded > budget)
      throw InputError(name, record, "",
                       "the file decodes to more than " + std::to_string(budget) +
                           " bytes, the most a rawlog may: the larger of " +
                           std::to_string(kMinRawlogBudgetBytes >> 20) + " MiB and " +
                           std::to_string(kMaxRawlogExpansion) + " times its size (a gzip bomb?)");
    mrpt::io::CMemoryStream memory;
    memory.assignMemoryNotOwn(bytes.data(), bytes.size());
    auto archive = mrpt::serialization::archiveFrom(memory);
    mrpt::serialization::CSerializable::Ptr object;
    try {
      object = archive.ReadObject();
    } catch (const std::exception& e) {
      // What our bounds do not cover: MRPT's own checks (a landmark id listed twice, ...).
      throw InputError(name, record, "", "unreadable record: " + mrpt_exception_message(e.what()));
    }
    log.records = record;
    if (auto actions = std::dynamic_pointer_cast<CActionCollection>(object)) {
      if (!any_action && !any_frame) log.sensory_frame_first = false;
      any_action = true;
      pending_odometry = odometry_of(*actions, name, record);
      if (!log.odometry_std) log.odometry_std = odometry_std_of(*actions);
    } else if (auto sf = std::dynamic_pointer_cast<CSensoryFrame>(object)) {
      if (!any_action && !any_frame) log.sensory_frame_first = true;
      any_frame = true;
      auto obs = sf->getObservationByClass<CObservationBearingRange>();
      auto scan = sf->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
      log.skipped_observations += static_cast<int>(sf->size()) - (obs ? 1 : 0) - (scan ? 1 : 0);
      if (scan) add_scan(log, *scan, pending_odometry, name, record);
      if (!obs) {
        if (scan) pending_odometry.reset();
        continue;
      }
      if (log.frames.empty()) log.sensor = sensor_of(*obs, name, record);
      RawlogFrame frame = frame_of(*obs, static_cast<int>(log.frames.size()), name, record);
      frame.odometry = pending_odometry;
      pending_odometry.reset();
      log.frames.push_back(std::move(frame));
    } else if (auto obs = std::dynamic_pointer_cast<CObservationBearingRange>(object)) {
      if (log.frames.empty()) log.sensor = sensor_of(*obs, name, record);
      log.format = Rawlog::Format::ObservationsOnly;
      RawlogFrame frame = frame_of(*obs, static_cast<int>(log.frames.size()), name, record);
      frame.odometry = pending_odometry;
      pending_odometry.reset();
      log.frames.push_back(std::move(frame));
    } else if (auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(object)) {
      log.format = Rawlog::Format::ObservationsOnly;
      add_scan(log, *scan, pending_odometry, name, record);
      pending_odometry.reset();
    } else if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(object)) {
      log.format = Rawlog::Format::ObservationsOnly;
      // Absolute odometry readings: the increment since the previous reading is the motion.
      if (auto increment = odometry_increment(*odo, last_odometry_reading, name, record)) pending_odometry = increment;
      last_odometry_reading = odo->odometry;
    } else {
      // read_checked_record admits no other class at the top level.
      throw std::logic_error(name + ": record " + std::to_string(record) + ": unexpected class " +
                             object->GetRuntimeClass()->className);
    }
  }
  if (log.frames.empty() && log.scans.empty())
    throw InputError(name, 0, "",
                     "no CObservationBearingRange or CObservation2DRangeScan in " + std::to_string(log.records) +
                         " records: nothing for a SLAM algorithm to read");
  if (any_action && any_frame) log.format = Rawlog::Format::ActionsSensoryFrames;
  return log;
}

}  // namespace

std::size_t rawlog_decoded_budget(std::uintmax_t stored_bytes) {
  return std::max<std::size_t>(kMinRawlogBudgetBytes, kMaxRawlogExpansion * static_cast<std::size_t>(stored_bytes));
}

Rawlog read_rawlog(const std::filesystem::path& path) {
  mrpt::io::CFileGZInputStream in;
  const std::size_t budget = rawlog_decoded_budget(open_rawlog(path, in));
  return read_records(in, path.string(), budget);
}

Rawlog read_laser_rawlog(const std::filesystem::path& path) {
  Rawlog log = read_rawlog(path);
  if (log.scans.empty())
    throw InputError(path.string(), 0, "",
                     "no CObservation2DRangeScan in " + std::to_string(log.records) +
                         " records: not a 2-D laser log (" + std::to_string(log.frames.size()) +
                         " bearing-range frames)");
  return log;
}

std::filesystem::path mrpt_datasets_folder() {
  return std::filesystem::path(mrpt::system::find_mrpt_shared_dir()) / "datasets";
}

Rawlog read_rawlog_bytes(std::string_view bytes, const std::string& name) {
  mrpt::io::CMemoryStream in;
  in.assignMemoryNotOwn(bytes.data(), bytes.size());
  return read_records(in, name, rawlog_decoded_budget(bytes.size()));
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
  Impl(const std::filesystem::path& path, bool gzip) : stream(path, gzip) {}
  RawlogRecordStream stream;
  RangeBearingSensor sensor;
};

RawlogWriter::RawlogWriter(const std::filesystem::path& path, const RangeBearingSensor& sensor, bool gzip)
    : impl_(std::make_unique<Impl>(path, gzip)) {
  impl_->sensor = sensor;
}

RawlogWriter::~RawlogWriter() = default;

void RawlogWriter::write(const ObservationFrame& frame, const std::vector<int>& landmark_ids, double timestamp_s) {
  CSensoryFrame sf;
  sf.insert(bearing_range_observation(frame, landmark_ids, impl_->sensor, timestamp_s));
  // Action first: kf-slam then pairs step k with frame k. Empty without odometry.
  impl_->stream.write(odometry_actions(frame), sf);
}

void RawlogWriter::close() { impl_->stream.close(); }

}  // namespace relslam::eval
