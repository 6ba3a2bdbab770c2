#pragma once
// MRPT's CObservation2DRangeScan as our LaserScan, checked as rawlog.hpp states. Internal to
// eval/io (rawlog.cpp).

#include "relslam/core/laser_scan.hpp"

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <string>

namespace relslam::eval {

// The scan in the planar half's frame (MRPT x, y, yaw -> x, z, heading), rays always in
// increasing bearing (a left-to-right scan is reversed). Throws InputError naming `file`,
// `record` and the field for a value outside rawlog.hpp's bounds.
LaserScan laser_scan_of(const mrpt::obs::CObservation2DRangeScan& obs, const std::string& file, int record);

}  // namespace relslam::eval
