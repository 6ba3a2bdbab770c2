#pragma once
// Rigid motions in 3D. Part of relslam/core: Eigen only.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace relslam {

// A rigid motion a_T_b: maps coordinates in frame b to frame a, p_a = rotation * p_b + translation.
// Invariant: rotation is orthonormal with determinant +1 (callers build it from rotations only).
// Frame names follow Sophus: world_T_robot * p_robot = p_world, and in a product the inner
// frame names must match (world_T_robot * robot_T_sensor = world_T_sensor).
struct Rigid3 {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();

  static Rigid3 identity() { return {}; }
  static Rigid3 from(const Eigen::Quaterniond& q, const Eigen::Vector3d& t) {
    return {q.normalized().toRotationMatrix(), t};
  }

  Eigen::Vector3d operator*(const Eigen::Vector3d& p_b) const { return rotation * p_b + translation; }
  Rigid3 operator*(const Rigid3& b_T_c) const {
    return {rotation * b_T_c.rotation, rotation * b_T_c.translation + translation};
  }
  Rigid3 inverse() const {
    const Eigen::Matrix3d rt = rotation.transpose();
    return {rt, -(rt * translation)};
  }
  // Maps p_a back into frame b without forming the inverse.
  Eigen::Vector3d inverse_apply(const Eigen::Vector3d& p_a) const { return rotation.transpose() * (p_a - translation); }
  Eigen::Quaterniond quaternion() const;
};

// Rotation of angle_rad about a unit axis (right-hand rule).
Eigen::Matrix3d rotation_about(const Eigen::Vector3d& unit_axis, double angle_rad);

}  // namespace relslam
