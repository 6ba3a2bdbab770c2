#pragma once
// How far a point lies inside a sensor's horizontal footprint (thesis 4.4.2's viewing frustum):
// the one formula the simulator's ViewingFrustum and Relative Plane's FieldOfView share.
// Part of relslam/core: Eigen only.

#include <Eigen/Core>

namespace relslam {

// The footprint in the robot frame (robot at the origin looking along +x, z lateral): within
// half_angle_rad of +x, at least `near` ahead, and at most `far` ahead (radial: at most `far`
// away). The distance of p_robot to its nearest edge (near line, far line or circle, a side),
// negative outside.
double frustum_depth(const Eigen::Vector2d& p_robot, double half_angle_rad, double near, double far, bool radial);

}  // namespace relslam
