#pragma once
// How stable extracted walls are from one scan to the next: the share of a scan's walls that
// have a counterpart among the previous scan's, once the robot's motion between the two is
// compensated. A wall the Relative Plane algorithm cannot match to its previous observation
// (Rule 1, thesis 4.3.1) starts a new RltPlane, so this share bounds how well local matching
// can do. Eigen only.

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"

#include <numbers>
#include <vector>

namespace relslam::scan {

// When two walls are the same [C]: directions within max_angle_rad (normals the same way), each
// one's midpoint within max_offset of the other's line, and overlapping along it.
struct CounterpartBounds {
  double max_angle_rad = 5.0 * std::numbers::pi / 180.0;
  double max_offset = 0.15;
};

// The length along a's line that b's projection shares with a (> 0 when they overlap).
double overlap(const PlaneObject& a, const PlaneObject& b);

// Whether `current` (in the current robot frame) has a counterpart in `previous` (in the
// previous robot frame); previous_T_current is the motion between the two.
bool has_counterpart(const PlaneObject& current, const std::vector<PlaneObject>& previous,
                     const PlanarPose& previous_T_current, const CounterpartBounds& bounds = {});

// Walls of `current` with a counterpart in `previous`.
int counterparts(const std::vector<PlaneObject>& current, const std::vector<PlaneObject>& previous,
                 const PlanarPose& previous_T_current, const CounterpartBounds& bounds = {});

}  // namespace relslam::scan
