#pragma once
// MRPT's CObservation2DRangeScan as our LaserScan, checked as rawlog.hpp states. Internal to
// eval/io (rawlog.cpp).

#include "relslam/core/laser_scan.hpp"

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <string>

namespace relslam::eval {

// rawlog.hpp's bounds for a scan (handed in: that header includes this one's user).
struct LaserScanLimits {
  double max_range = 0;          // maxRange at most this
  double range_tolerance = 0;    // valid ranges up to (1 + this) maxRange
  double max_sensor_offset = 0;  // each coordinate of the scanner's pose on the robot, m
  double max_tilt_rad = 0;       // its pitch and roll
};

// The scan in the planar half's frame (MRPT x, y, yaw -> x, z, heading), rays always in
// increasing bearing (a left-to-right scan is reversed). Throws InputError naming `file`,
// `record` and the field for a value outside `limits`.
LaserScan laser_scan_of(const mrpt::obs::CObservation2DRangeScan& obs, const LaserScanLimits& limits,
                        const std::string& file, int record);

}  // namespace relslam::eval
