#pragma once
// Evidence against a place (beyond the thesis; the adaptive preset's relocalisation,
// pose_integrity.hpp): a place found by matching the planes in view against the whole map can
// fit them by chance, most of all while the robot's true place is not on the map yet. The map
// then says what else the sensor would see there: a mapped wall well inside the field of view
// (not behind the robot's back, not hidden by another wall where the sensor has occlusion) that
// no plane in view covers, or a plane in view that would pass through a mapped wall, rules the
// place out. The robot's own place passes, up to walls the map holds wrongly (a conservative
// miss: the pose stays lost a little longer). Part of relslam/plane: Eigen only.

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"
#include "relslam/plane/field_of_view.hpp"

#include <span>
#include <string_view>

namespace relslam::plane {

enum class ViewConflict : unsigned char {
  None,        // nothing the map shows there contradicts the planes in view
  UnseenWall,  // a mapped wall that should be in view is not
  Crossing,    // a plane in view would pass through a mapped wall
};
std::string_view to_string(ViewConflict conflict);  // "none", "unseen_wall", "crossing"

// The bounds a plane in view must keep to cover a mapped wall: its distance to the wall's line,
// units, and its direction, radians (the pose check's bounds, pose_integrity.hpp, doubled).
struct CoverBounds {
  double offset = 0.1;
  double angle_rad = 0.05;
};

// What the map (world frame) says against the robot standing at `world_T_robot` while seeing
// `seen` (robot frame) through `view`. None when view.known is false.
ViewConflict view_conflict(const PlanarPose& world_T_robot, std::span<const PlaneObject> seen,
                           std::span<const PlaneObject> map, const FieldOfView& view,
                           const ViewEvidenceOptions& options, const CoverBounds& cover);

}  // namespace relslam::plane
