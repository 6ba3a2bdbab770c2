#pragma once
// Placing walls and groups by the walls' lines (beyond the thesis; the adaptive preset's
// relative_plane.place_by_lines). Relative Plane places a plane through a group's comparisons
// (Rules 13-15: a pair of ends at a fixed offset) and a group through the linking planes it
// shares with a placed group (Rules 8, 12). A wall a laser sees only in pieces, every end cut by
// an occluder, the scan's edge or the maximum range, has no end a comparison can hold on: its
// groups stay unplaced, so does every group linked through them, and once the robot has left the
// placed walls behind no pose is found again until it returns to them.
//
// The line of a wall needs no end. Where the lines of two or more mapped walls in two directions
// fix the pose and agree with the map (pose_integrity.hpp), each other wall in view lies, under
// that pose, where the walls seen with it put it: placed relative to them, in the same scan.
// When it lies on one line in several such iterations it goes onto the map as that line, as long
// as it has been seen along it. And a group no link places is placed where two or more of its
// planes in two directions lie on their walls on the map: the map confirms the group's own
// geometry within the pose check's bounds, scaled with the sensor noise.
// Part of relslam/plane: Eigen only.

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"
#include "relslam/plane/pose_integrity.hpp"

#include <optional>
#include <span>
#include <vector>

namespace relslam::plane {

// What one RltPlane's lines said of where it lies, while no group places it.
struct LinePlacement {
  // Its observations put into the world by checked poses, oldest first, until it is placed.
  std::vector<PlaneObject> samples;
  bool placed = false;
  PlaneObject world;  // placed: its line, between the farthest points seen along it
};

// The bounds a line placement is held to: the pose check's (IntegrityOptions::offset_bound,
// angle_bound_rad, min_angle_rad), and the samples it needs.
struct LinePlacementOptions {
  int samples = 4;
  double offset_bound = 0.05;
  double angle_bound_rad = 0.026;
  double min_angle_rad = 0.35;
};

// Whether `seen` (world frame) lies on `line`'s line: its direction within angle_bound_rad and
// both its ends within offset_bound of the line.
bool on_line(const PlaneObject& line, const PlaneObject& seen, const LinePlacementOptions& options);

// The mean line of `samples` (world frame, facing the same way), between the farthest points of
// any sample along it.
PlaneObject mean_line(std::span<const PlaneObject> samples);

// `line` lengthened to cover `seen`'s projection onto it.
PlaneObject extended(const PlaneObject& line, const PlaneObject& seen);

// One iteration's evidence: `seen` (world frame, under a checked pose) added to `placement`. An
// unplaced wall keeps its last options.samples observations and is placed once each lies on
// their mean line; a placed one grows along its line by the observations that lie on it.
void add_line_evidence(LinePlacement& placement, const PlaneObject& seen, const LinePlacementOptions& options);

// Where a group lies from its planes (group frame) and the walls on the map they are (world
// frame), as LinePairs: fitted to the lines and valid only when two directions are in it and every
// pair lies on its wall's line (on_line; the extent is not compared, as a group's piece of a wall
// and the map's need not overlap).
std::optional<PlanarPose> place_on_lines(std::span<const LinePair> pairs, const LinePlacementOptions& options);

}  // namespace relslam::plane
