#pragma once
// One 2-D laser scan, the raw input from which walls are extracted for the Relative Plane half
// (thesis Chapter 4 maps walls; the thesis simulated them, real indoor robots see them with a
// planar laser). Part of relslam/core: Eigen only.
//
// Frame: the planar half's (planar_pose.hpp). Ray i leaves the sensor at the bearing
// start_bearing + i * bearing_step, measured from the sensor's +x towards +z, the turning sense
// of PlanarPose::heading. A recorded scan in MRPT's convention (x forward, y left, yaw about +z)
// maps as x -> x, y -> z, yaw -> heading; that mapping is made once where scans are read or
// written (rawlog reader and writer).

#include "relslam/core/planar_pose.hpp"

#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace relslam {

struct LaserScan {
  double stamp_s = 0;                  // the log's time stamp, s (0 where unknown)
  PlanarPose robot_T_sensor;           // where the scanner sits on the robot
  double start_bearing_rad = 0;        // bearing of ranges[0], sensor frame
  double bearing_step_rad = 0;         // between consecutive rays; > 0
  double max_range = 0;                // the scanner's maximum range (same units as ranges)
  std::vector<float> ranges;           // one per ray
  std::vector<char> valid;             // one per ray: 1 a return, 0 none (no echo, out of range)

  std::size_t size() const { return ranges.size(); }
  double bearing(std::size_t i) const { return start_bearing_rad + static_cast<double>(i) * bearing_step_rad; }
  // Ray i's return in the sensor frame (x, z); meaningful where valid[i].
  Eigen::Vector2d point(std::size_t i) const {
    const double b = bearing(i);
    return static_cast<double>(ranges[i]) * Eigen::Vector2d(std::cos(b), std::sin(b));
  }
};

}  // namespace relslam
