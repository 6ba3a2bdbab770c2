#include "relslam/eval/range_bearing.hpp"

#include <algorithm>
#include <cmath>

namespace relslam::eval {

RangeBearing range_bearing_of(const Eigen::Vector3d& p) {
  const double range = p.norm();
  if (range == 0.0) return {};
  // asin of a ratio clamped to [-1, 1]: rounding can push |z| / range a hair above 1.
  const double ratio = std::clamp(p.z() / range, -1.0, 1.0);
  return {range, std::atan2(p.y(), p.x()), -std::asin(ratio)};
}

Eigen::Vector3d point_of(const RangeBearing& m) {
  const double horizontal = m.range * std::cos(m.pitch_rad);
  return {horizontal * std::cos(m.yaw_rad), horizontal * std::sin(m.yaw_rad), -m.range * std::sin(m.pitch_rad)};
}

Rigid3 robot_axes_from_mrpt(const Rigid3& mrpt_pose) {
  Eigen::Matrix3d a;  // p_ours = A p_mrpt: x_ours = y_m, y_ours = z_m, z_ours = x_m
  a << 0, 1, 0, 0, 0, 1, 1, 0, 0;
  return {a * mrpt_pose.rotation * a.transpose(), a * mrpt_pose.translation};
}

}  // namespace relslam::eval
