#pragma once
// A path's centre line, parameterised by horizontal arc length. Part of relslam/sim.

#include <Eigen/Core>

namespace relslam::sim {

// One point of a centre line in the frame it was designed in (y up).
struct CenterlinePoint {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d tangent = Eigen::Vector3d::UnitZ();  // unit direction of travel, slope included
  Eigen::Vector3d left = Eigen::Vector3d::UnitX();     // unit horizontal normal, left of travel
};

// A closed or open curve the robot follows and the point band is generated around.
class Centerline {
 public:
  virtual ~Centerline() = default;
  // Horizontal arc length of one pass.
  virtual double length() const = 0;
  // s in [0, length()); closed curves also accept any s and wrap it.
  virtual CenterlinePoint at(double s) const = 0;
};

}  // namespace relslam::sim
