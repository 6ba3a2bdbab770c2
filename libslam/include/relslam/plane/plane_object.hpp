#pragma once
// PlaneObject's operations of thesis 4.4.3.12 — MatchPlane, AdjustSize, GetKeyPoints,
// CalculateOffset — as free functions over the core value type.
// Part of relslam/plane: Eigen only.

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"

#include <Eigen/Core>

#include <numbers>

namespace relslam::plane {

// Rule 14: with the plane turned to 0° (normal along +z), its left end `a` is key point 1 and
// its right end `b` key point 2; None when no end is known to be static.
enum class KeyPoint : unsigned char { None = 0, Left = 1, Right = 2 };

// The bounds of MatchPlane (thesis 4.3.1). The in-class values are the local ones (Rule 1:
// an RltPlane's previous observation against this iteration's); global_match_defaults() holds
// the looser ones of Rule 11.
struct MatchBounds {
  // Rule 10: the normals may differ by at most this angle. Covers a turn of several
  // iterations plus rotation noise [R, c_dot = cos 15°].
  double max_normal_angle_rad = 15.0 * std::numbers::pi / 180.0;
  // |d_prev − d_cur|, map units: the robot's motion towards the plane between the two
  // observations plus noise [R, c_d].
  double max_offset_change = 0.3;
  // The 3-D boxes are widened by this margin before the corner test: a vertical wall
  // along an axis has a box of zero thickness [R, m_bb].
  double box_margin = 0.25;
  // Along the plane the two must overlap by at least this share of the shorter one, so a
  // collinear neighbour segment is not taken for the same plane [P "the overlap must be
  // sufficient"; R value f_ovl].
  double min_overlap_fraction = 0.2;
  // At most this many iterations between the two observations: a plane that left the view
  // must not be taken over by another that appears at the same relative place later [T];
  // negative: no iteration test (global matching) [R, c_gap].
  int max_iteration_gap = 5;
  // The offset test allows the part of |d_prev − d_cur| that the normals' angle explains as a
  // turn of the plane about its own midpoint: the sensor's rotation noise turns each plane about
  // its midpoint, which moves the offset by the midpoint's distance along the plane
  // from the foot of the perpendicular times the angle (0.3° at 27 units along: 0.14), while
  // the robot's own turn leaves d unchanged. Off: the thesis's bare offset test, under which a
  // far wall in the large frustum fails Rule 1 and is mapped twice [C].
  bool rotation_about_midpoint = true;
};

// Rule 11's bounds: room for the pose error of backtracking [R, c_dot_g, c_d_g,
// m_bb_g]; no iteration test.
inline MatchBounds global_match_defaults() { return {20.0 * std::numbers::pi / 180.0, 0.5, 0.5, 0.2, -1}; }

// MatchPlane (thesis 4.5; thesis 4.3.1): the score in [0, 100] of `current` as the same plane as
// `previous`, or -1 when any test fails: normal direction (Rule 10; with
// `same_normal_direction` false a flipped normal passes), offset, box corners and centres
// (18 points, at least one inside the other box) with the tangent overlap, iteration gap.
// Four tests of 25 points each, so the best of several candidates can be chosen [T].
double match_plane(const PlaneObject& previous, const PlaneObject& current, const MatchBounds& bounds,
                   bool same_normal_direction = true);

// GetKeyPoints: the top corner of key point k (Rule 14); logic_error for None.
Eigen::Vector2d key_point(const PlaneObject& plane, KeyPoint k);
// The assumed midpoint (thesis 4.3.4): half of `length` along the plane from key point k.
Eigen::Vector2d assumed_midpoint(const PlaneObject& plane, double length, KeyPoint k);
// AdjustSize (thesis 4.2.3): the plane grown or shrunk to `length` with key point k fixed;
// logic_error for None (without a static end the size change has no anchor, thesis 4.3.4).
PlaneObject adjust_size(const PlaneObject& plane, double length, KeyPoint k);

// Re-anchoring (thesis 4.2.3; Rules 16, 17, 28): `pose` is a plane's reference point at `length`,
// anchored on key point k; the result is the reference point at `new_length` on the same
// static end: pose ∘ Trans(s_k·(new_length − length)/2, 0), s_Left = +1, s_Right = −1. With k
// None the point cannot move (thesis 4.3.4): `pose` is returned unchanged.
PlanarPose reanchor(const PlanarPose& pose, double length, double new_length, KeyPoint k);

// CalculateOffset (thesis 4.3.1, Rule 5): the robot pose that puts `observed` (robot frame) onto
// `mapped` (world frame): world_T_robot = P_mapped ∘ P_observed⁻¹. Both must have the same size
// (grow the observation first, Rule 16).
PlanarPose calculate_offset(const PlaneObject& mapped, const PlaneObject& observed);

}  // namespace relslam::plane
