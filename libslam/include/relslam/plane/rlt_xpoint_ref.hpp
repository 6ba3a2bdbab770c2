#pragma once
// RltXPointRef (thesis 4.4.3.5; spec §5.2): one RltPlane's membership of one RltXPoint, with
// the plane's place in that group's relative map.

#include "relslam/core/planar_pose.hpp"
#include "relslam/plane/ids.hpp"
#include "relslam/plane/plane_object.hpp"
#include "relslam/plane/rlt_interval.hpp"

namespace relslam::plane {

// Written by RltXPoint::compute (ComputeXPoint), read by RltMapBuilder. Part 2 adds the
// confirmation flag (Rules 31/32), the reserve copies (Rule 36) and the static-end flag.
struct RltXPointRef {
  XPointId xpoint = kNone;
  // False until a comparison placed the plane (or when its comparison interval is empty).
  bool valid = false;
  // x_T_plane: the plane's reference point — its midpoint at max_length, anchored on key_point
  // — and direction in the group's frame (spec §5.7.2).
  PlanarPose pose;
  RltInterval interval;  // first and last iteration of the comparison that placed it
  int samples = 0;       // iterations that comparison averaged
  KeyPoint key_point = KeyPoint::None;
  // Part 2: the plane kept its size in the comparison that gave max_length (spec §5.6.4), so it
  // needs no key point to be placed at that size.
  bool size_static = false;
  double max_length = 0;
  double height = 0;
  int join_iteration = 0;  // when the plane joined the group [R: roll-back, Rule 33]
  // Rules 31/32 (CheckIntervalSize): the comparison placing the plane reached the minimum
  // interval, so it is not checked again ...
  bool confirmed = false;
  // ... or it did not in time and a hint was sent back (Rule 34); still here only when that
  // roll-back was refused, and then not checked again either.
  bool hinted = false;
};

}  // namespace relslam::plane
