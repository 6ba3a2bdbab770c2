#pragma once
// Poses in the horizontal plane, for the Relative Plane half (thesis Chapter 4).
// Part of relslam/core: Eigen only.
//
// The planar world is 2½D: everything is solved in the (x, z) plane, y is up and only carries
// the walls' height, and the robot turns about y only. A pose T = (t, ψ) maps robot-frame
// points to the world: p_W = Rot(ψ) p_R + t, with Rot(α) = [[cos α, −sin α], [sin α, cos α]]
// acting on (x, z) column vectors. The robot looks along its +x; ψ = 0 faces world +x and
// ψ = +90° faces world +z. (In a right-handed 3-D frame with y up this turn is about −y:
// rigid_from_planar() makes that one conversion, for TUM files.)

#include "relslam/core/rigid.hpp"

#include <Eigen/Core>

namespace relslam {

// The angle in (−π, π].
double wrap_angle(double angle_rad);
// Rot(α) on (x, z).
Eigen::Matrix2d planar_rotation(double angle_rad);

// a_T_b in the plane, named like Rigid3 (world_T_robot * p_robot = p_world).
struct PlanarPose {
  Eigen::Vector2d translation = Eigen::Vector2d::Zero();  // (x, z)
  double heading = 0;                                     // ψ, rad, kept in (−π, π]

  static PlanarPose identity() { return {}; }
  static PlanarPose from(double x, double z, double heading_rad) { return {{x, z}, wrap_angle(heading_rad)}; }

  Eigen::Vector2d operator*(const Eigen::Vector2d& p_b) const { return planar_rotation(heading) * p_b + translation; }
  // T_a ∘ T_b = (t_a + Rot(ψ_a) t_b, ψ_a + ψ_b).
  PlanarPose operator*(const PlanarPose& b_T_c) const {
    return {planar_rotation(heading) * b_T_c.translation + translation, wrap_angle(heading + b_T_c.heading)};
  }
  // T⁻¹ = (−Rot(−ψ) t, −ψ).
  PlanarPose inverse() const { return {-(planar_rotation(-heading) * translation), wrap_angle(-heading)}; }
  // Maps p_a back into frame b without forming the inverse.
  Eigen::Vector2d inverse_apply(const Eigen::Vector2d& p_a) const {
    return planar_rotation(-heading) * (p_a - translation);
  }
};

// The planar pose as a 3-D rigid motion at height y (x, y, z with y up): the turn by ψ from +x
// towards +z is a rotation about −y.
Rigid3 rigid_from_planar(const PlanarPose& pose, double y = 0.0);

}  // namespace relslam
