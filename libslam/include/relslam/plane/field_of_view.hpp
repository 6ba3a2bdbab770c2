#pragma once
// The sensor's field of view as Relative Plane's relocalisation sees it (beyond the thesis; the
// adaptive preset): where, from a pose, a mapped wall would be in view. The thesis's algorithm
// never asks (its simulator's ViewingFrustum culls planes before the algorithm sees them, thesis
// 4.4.2); relocalisation does, to tell a place that fits the planes in view by chance from the
// robot's: at a wrong place the map shows walls the sensor should see there and does not
// (view_evidence.hpp). The harness fills it from the scenario's frustum; unset, no place is
// judged by it. Part of relslam/plane: Eigen only.

#include <Eigen/Core>

#include <numbers>

namespace relslam::plane {

struct FieldOfView {
  // Whether the rest describes the sensor; false: relocalisation uses no evidence against a place.
  bool known = false;
  // The footprint in the robot frame (robot at the origin looking along +x, z lateral): within
  // half_angle_rad of +x, at least `near` ahead and at most `far` ahead (radial: at most `far`
  // away). The defaults are the thesis's small frustum (thesis 4.4.2).
  double half_angle_rad = 30.0 * std::numbers::pi / 180.0;
  double near = 0.1;
  double far = 7.0;
  bool radial = false;
  // A wall hides the walls behind it (a laser or depth sensor's points); the thesis's plane sensor
  // sees planes through others (thesis Fig 100).
  bool occlusion = false;
  // A wall is seen from its front face only (the simulator's backface culling).
  bool front_face_only = true;

  // How far p_robot lies inside the footprint: its distance to the nearest edge, negative outside.
  double depth(const Eigen::Vector2d& p_robot) const;
};

// How a place is judged against the field of view [C throughout: the thesis has no such test].
struct ViewEvidenceOptions {
  // A mapped wall counts as one the sensor should see only where it lies this far inside the
  // footprint, units: the place is known to within the integrity bounds only, and a wall at the
  // footprint's edge may be seen or not.
  double edge_margin = 0.4;
  // A place is ruled out when more than this length of mapped walls that should be in view there
  // is not covered by planes in view on their lines, units, counted per wall: a wall the map
  // shows where the sensor sees none, or going on past where the sensor saw its real end.
  double max_unseen = 1.0;
  // Walls are sampled along their length this finely, units.
  double sample_step = 0.1;
  // A plane in view that crosses a mapped wall (more than this inside both) cannot be where the
  // place puts it, units: walls do not pass through each other.
  double crossing_margin = 0.3;
};

}  // namespace relslam::plane
