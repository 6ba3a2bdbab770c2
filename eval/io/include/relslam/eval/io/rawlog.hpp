#pragma once
// MRPT rawlogs: the per-iteration observation stream as MRPT's tools (rawlog-edit, kf-slam,
// RawLogViewer) read it. This header hides MRPT: callers see only our types.

#include "relslam/core/laser_scan.hpp"
#include "relslam/core/observation.hpp"
#include "relslam/core/planar_pose.hpp"
#include "relslam/core/rigid.hpp"
#include "relslam/eval/io/range_bearing.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace relslam::eval {

struct RawlogMeasurement {
  float range = 0;
  float yaw_rad = 0;
  float pitch_rad = 0;
  std::int32_t landmark_id = -1;  // -1: unknown association
};

// One sensory frame (or, in observation-only files, one bearing-range observation).
struct RawlogFrame {
  int index = 0;           // 0-based, in file order
  double timestamp_s = 0;  // MRPT time as seconds since the epoch
  Rigid3 robot_T_sensor;   // MRPT's sensorLocationOnRobot, in MRPT's robot frame
  std::vector<RawlogMeasurement> measurements;
  // Odometry since the previous frame, when the file has any (MRPT's robot frame: x forward,
  // y left, z up). In action-first files it is the action just before this frame; in the
  // sensory-frame-first files MRPT's own simulator writes it is the action after the previous
  // frame — the same motion, so frame k always pairs with ground-truth row k.
  std::optional<Rigid3> odometry;
};

// One 2-D laser scan (CObservation2DRangeScan) in the planar half's frame (laser_scan.hpp:
// MRPT's x, y, yaw become x, z, heading), with the odometry since the previous scan paired as
// for RawlogFrame.
struct RawlogScan {
  int index = 0;  // 0-based among the scans, in file order
  LaserScan scan;
  std::optional<PlanarPose> odometry;
};

// An odometry action's own uncertainty (its Gaussian's diagonal): the largest translation and
// the largest rotation standard deviation.
struct OdometryStd {
  double xyz_m = 0;
  double angle_rad = 0;
};

struct Rawlog {
  enum class Format { ActionsSensoryFrames, ObservationsOnly };
  Format format = Format::ActionsSensoryFrames;
  // True for files written SF, action, SF, ... (MRPT's simul-landmarks). kf-slam drops their
  // first frame, so its step k is our frame k + 1; we keep every frame.
  bool sensory_frame_first = false;
  int records = 0;               // serialized objects read
  int skipped_observations = 0;  // observations of other types, ignored
  RangeBearingSensor sensor;     // as the first bearing-range observation describes it
  std::optional<OdometryStd> odometry_std;  // as the first odometry action with a covariance states it
  std::vector<RawlogFrame> frames;
  std::vector<RawlogScan> scans;  // 2-D laser scans, where the log has them
};

// The reader's limits besides the per-record bounds of its framing check (16 MiB a record,
// every count checked before it is allocated):
//
// The whole file decodes to at most the larger of kMinRawlogBudgetBytes and kMaxRawlogExpansion
// times its size on disk. Every frame is kept in memory, so this bounds memory by the file's
// size: landmark readings (floats) compress about 2:1, while a gzip bomb of zeros compresses
// 1000:1 (a 995 KB file of eight records took 1.15 GB). A plain file never reaches it.
inline constexpr std::size_t kMinRawlogBudgetBytes = std::size_t{64} << 20;
inline constexpr std::size_t kMaxRawlogExpansion = 64;
// That budget for a file of `stored_bytes` on disk (the point-cloud reader's too).
std::size_t rawlog_decoded_budget(std::uintmax_t stored_bytes);
// What a bearing-range observation says about its sensor must make sense, not only be finite
// (a negative field of view, a maximum range below the minimum or readings of 3e38 ran the EKF
// for minutes; a sensor 1e300 away from the robot gave NaN):
//   fieldOfView_yaw in (0, 2 pi], fieldOfView_pitch in [0, 2 pi] (0: a planar sensor);
//   0 <= minSensorDistance;
//   maxSensorDistance <= kMaxSensorRange_m and above minSensorDistance, unless both are 0
//   (MRPT's default: no range given); readings in [0, (1 + kRangeTolerance) maxSensorDistance]
//   when a maximum is given (MRPT's simulator adds noise after it culls by range); yaw and
//   pitch in [-2 pi, 2 pi]; sensor noise deviations >= 0; each coordinate of the sensor's pose
//   on the robot within +-kMaxSensorOffset_m.
inline constexpr double kMaxSensorRange_m = 1e6;
inline constexpr double kRangeTolerance = 0.1;
inline constexpr double kMaxSensorOffset_m = 1e3;
// Odometry: each coordinate of an increment (an action, or the difference of two consecutive
// CObservationOdometry readings) within +-kMaxOdometryStep_m, of a reading within
// +-kMaxOdometryReading_m, so that composing them cannot overflow (two finite readings of
// opposite sign 1e308 differ by infinity).
inline constexpr double kMaxOdometryStep_m = 1e4;
inline constexpr double kMaxOdometryReading_m = 1e9;

// A 2-D laser scan (CObservation2DRangeScan versions 6 and 7) must likewise make sense:
// aperture in (0, 2 pi]; maxRange in (0, kMaxSensorRange_m]; at least 2 rays; every valid
// range finite and in [0, (1 + kRangeTolerance) maxRange] (invalid ones are not read); the
// sensor's pose on the robot within +-kMaxSensorOffset_m and level: pitch and roll within
// kMaxScanTilt_rad, since the scan is taken as a horizontal slice of the walls.
inline constexpr double kMaxScanTilt_rad = 0.1;

// Reads plain or gzip files of either MRPT format. Throws InputError (file, record number,
// field, problem) for a missing, foreign, truncated or empty file, a class we do not accept,
// a count beyond what a record may hold, a file decoding to more than its budget above, a
// non-finite value or one outside the ranges above. Accepted at the top level:
// CActionCollection (of CActionRobotMovement2D/3D), CSensoryFrame (of CObservationBearingRange,
// CObservation2DRangeScan and CObservationOdometry), CObservationBearingRange,
// CObservation2DRangeScan, CObservationOdometry; README.md lists the versions. A log needs
// bearing-range frames or laser scans (read_laser_rawlog below requires scans).
Rawlog read_rawlog(const std::filesystem::path& path);

// read_rawlog for a log of 2-D laser scans: InputError as read_rawlog's, and when the log
// holds no CObservation2DRangeScan.
Rawlog read_laser_rawlog(const std::filesystem::path& path);

// Where MRPT's installed data sets are (the Debian package mrpt-common puts them in
// /usr/share/mrpt/datasets); the folder may not exist.
std::filesystem::path mrpt_datasets_folder();

// The same reader over a plain (not gzip) rawlog already in memory, `name` standing for the
// file in messages: what the fuzz target calls.
Rawlog read_rawlog_bytes(std::string_view bytes, const std::string& name);

// Robot-frame points (our axes: +x left, +y up, +z forward) of one frame, after applying
// the sensor's pose on the robot. The algorithms' view of a rawlog.
ObservationFrame observation_frame(const RawlogFrame& frame);

// MRPT reads a timestamp of 0 as "no timestamp", so simulated runs put iteration k at this
// time plus k seconds in rawlogs (2001-09-09 onwards); TUM files use plain k.
inline constexpr double kSimulationEpoch_s = 1.0e9;

// Writes action-first rawlogs (empty CActionCollection, then one sensory frame holding one
// CObservationBearingRange per iteration), the order kf-slam pairs without an offset.
class RawlogWriter {
 public:
  RawlogWriter(const std::filesystem::path& path, const RangeBearingSensor& sensor, bool gzip);
  ~RawlogWriter();
  RawlogWriter(const RawlogWriter&) = delete;
  RawlogWriter& operator=(const RawlogWriter&) = delete;

  // Points in our robot frame; landmark_ids parallel to frame.points, or empty for -1.
  void write(const ObservationFrame& frame, const std::vector<int>& landmark_ids, double timestamp_s);
  void close();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace relslam::eval
