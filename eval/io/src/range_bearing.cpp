#include "relslam/eval/io/range_bearing.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

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

namespace {

// p_ours = A p_mrpt: x_ours = y_m, y_ours = z_m, z_ours = x_m.
Eigen::Matrix3d ours_from_mrpt_axes() {
  Eigen::Matrix3d a;
  a << 0, 1, 0, 0, 0, 1, 1, 0, 0;
  return a;
}

}  // namespace

Rigid3 robot_axes_from_mrpt(const Rigid3& mrpt_pose) {
  const Eigen::Matrix3d a = ours_from_mrpt_axes();
  return {a * mrpt_pose.rotation * a.transpose(), a * mrpt_pose.translation};
}

Rigid3 mrpt_axes_from_robot(const Rigid3& pose) {
  const Eigen::Matrix3d a = ours_from_mrpt_axes();
  return {a.transpose() * pose.rotation * a, a.transpose() * pose.translation};
}

Rigid3 robot_pose_from_planar(const Pose2& pose) {
  return robot_axes_from_mrpt(
      {Eigen::AngleAxisd(pose.heading, Eigen::Vector3d::UnitZ()).toRotationMatrix(), {pose.x, pose.y, 0.0}});
}

Pose2 planar_from_robot_pose(const Rigid3& pose) {
  const Rigid3 m = mrpt_axes_from_robot(pose);
  return {m.translation.x(), m.translation.y(), std::atan2(m.rotation(1, 0), m.rotation(0, 0))};
}

}  // namespace relslam::eval
