#pragma once
// Converting between our robot frame and MRPT's range/yaw/pitch measurements.
// Ours (thesis): +x left, +y up, +z forward. MRPT's sensor frame: +x forward, +y left, +z up.
// (x_m, y_m, z_m) = (z_r, x_r, y_r) is a proper rotation (a cyclic permutation of the axes).

#include "relslam/core/rigid.hpp"

#include <Eigen/Core>

namespace relslam::eval {

// MRPT's convention (CPose3D::sphericalCoordinates): range = |p|, yaw = atan2(y, x) (0 ahead,
// counter-clockwise positive), pitch = -asin(z / range) (NEGATIVE elevation: pitch > 0 is below).
struct RangeBearing {
  double range = 0;
  double yaw_rad = 0;
  double pitch_rad = 0;
};

inline Eigen::Vector3d mrpt_from_robot(const Eigen::Vector3d& p_robot) {
  return {p_robot.z(), p_robot.x(), p_robot.y()};
}
inline Eigen::Vector3d robot_from_mrpt(const Eigen::Vector3d& p_mrpt) { return {p_mrpt.y(), p_mrpt.z(), p_mrpt.x()}; }
// A pose between two frames that both use MRPT's axes, re-expressed with ours: A · pose · A^-1.
Rigid3 robot_axes_from_mrpt(const Rigid3& mrpt_pose);
// The inverse: a pose in our axes re-expressed with MRPT's.
Rigid3 mrpt_axes_from_robot(const Rigid3& pose);

// A planar pose or motion in MRPT's axes (x forward, y left), heading counter-clockwise.
struct Pose2 {
  double x = 0, y = 0;  // m
  double heading = 0;   // rad
};
// Between a planar MRPT pose and a pose in our axes (a rotation about our +y, up); the
// vertical part of a Rigid3 is dropped.
Rigid3 robot_pose_from_planar(const Pose2& pose);
Pose2 planar_from_robot_pose(const Rigid3& pose);

// p in MRPT's sensor frame -> measurement; range 0 gives yaw = pitch = 0.
RangeBearing range_bearing_of(const Eigen::Vector3d& p_mrpt);
// MRPT's inverse model: (r cos yaw cos pitch, r sin yaw cos pitch, -r sin pitch).
Eigen::Vector3d point_of(const RangeBearing& m);

// Sensor description written into every CObservationBearingRange. MRPT's EKF gates landmark
// predictions with these, so they must describe the real sensor.
struct RangeBearingSensor {
  double min_range = 0.0;
  double max_range = 0.0;
  double field_of_view_yaw_rad = 0.0;
  double field_of_view_pitch_rad = 0.0;
  double std_range = 0.0;  // informative only: MRPT's EKFs ignore them
  double std_yaw_rad = 0.0;
  double std_pitch_rad = 0.0;
};

}  // namespace relslam::eval
