#include "relslam/core/plane_object.hpp"

#include <cmath>

namespace relslam {

double PlaneObject::angle() const {
  const Eigen::Vector2d d = b - a;
  return std::atan2(d.y(), d.x());
}

PlaneObject PlaneObject::from_pose(const PlanarPose& pose, double length, double y_lo, double y_hi, int iteration) {
  const Eigen::Vector2d u(std::cos(pose.heading), std::sin(pose.heading));
  return {pose.translation - 0.5 * length * u, pose.translation + 0.5 * length * u, y_lo, y_hi, iteration};
}

PlaneObject PlaneObject::transformed(const PlanarPose& a_T_b) const {
  PlaneObject out = *this;
  out.a = a_T_b * a;
  out.b = a_T_b * b;
  return out;
}

}  // namespace relslam
