#include "laser_scan_record.hpp"

#include "relslam/core/option_issue.hpp"
#include "relslam/eval/config/input_error.hpp"

#include <mrpt/core/Clock.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>
#include <numbers>

namespace relslam::eval {
namespace {

// The scanner's pose on the robot as a planar pose: finite, within limits.max_sensor_offset, level.
PlanarPose sensor_pose_of(const mrpt::poses::CPose3D& p, const LaserScanLimits& limits, const std::string& file,
                          int record) {
  const double values[] = {p.x(), p.y(), p.z(), p.yaw(), p.pitch(), p.roll()};
  for (double v : values)
    if (!std::isfinite(v)) throw InputError(file, record, "sensorPose", "pose must be finite");
  for (double v : {p.x(), p.y(), p.z()})
    if (std::abs(v) > limits.max_sensor_offset)
      throw InputError(file, record, "sensorPose",
                       "each coordinate must be within +-" + format_number(limits.max_sensor_offset) + " m, got " +
                           format_number(v));
  if (std::abs(p.pitch()) > limits.max_tilt_rad || std::abs(p.roll()) > limits.max_tilt_rad)
    throw InputError(file, record, "sensorPose",
                     "the scanner must be level (pitch and roll within +-" + format_number(limits.max_tilt_rad) +
                         " rad), got pitch " + format_number(p.pitch()) + ", roll " + format_number(p.roll()));
  return PlanarPose::from(p.x(), p.y(), p.yaw());
}

}  // namespace

LaserScan laser_scan_of(const mrpt::obs::CObservation2DRangeScan& obs, const LaserScanLimits& limits,
                        const std::string& file, int record) {
  const std::size_t n = obs.getScanSize();
  const double aperture = obs.aperture;
  const double max_range = obs.maxRange;
  if (!(aperture > 0 && aperture <= 2 * std::numbers::pi))
    throw InputError(file, record, "aperture", "must be in (0, 2 pi], got " + format_number(aperture));
  if (!(max_range > 0 && max_range <= limits.max_range))
    throw InputError(file, record, "maxRange",
                     "must be in (0, " + format_number(limits.max_range) + "] m, got " + format_number(max_range));
  if (n < 2) throw InputError(file, record, "scan", "at least 2 rays needed, got " + std::to_string(n));
  LaserScan scan;
  scan.stamp_s = obs.timestamp == INVALID_TIMESTAMP ? 0.0 : mrpt::Clock::toDouble(obs.timestamp);
  scan.robot_T_sensor = sensor_pose_of(obs.sensorPose, limits, file, record);
  scan.bearing_step_rad = aperture / static_cast<double>(n - 1);
  scan.start_bearing_rad = -0.5 * aperture;
  scan.max_range = max_range;
  scan.ranges.resize(n);
  scan.valid.resize(n);
  const double limit = (1.0 + limits.range_tolerance) * max_range;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = obs.rightToLeft ? i : n - 1 - i;  // MRPT's ray for our ray i
    const float r = obs.getScanRange(k);
    const bool valid = obs.getScanRangeValidity(k);
    if (valid && !(std::isfinite(r) && r >= 0 && r <= limit))
      throw InputError(file, record, "scan[" + std::to_string(k) + "]",
                       "a valid range must be in [0, " + format_number(limit) + "] m (maxRange " +
                           format_number(max_range) + " + " + format_number(100 * limits.range_tolerance) +
                           " %), got " + std::to_string(r));
    scan.ranges[i] = valid ? r : 0.0f;
    scan.valid[i] = valid ? 1 : 0;
  }
  return scan;
}

}  // namespace relslam::eval
