#pragma once
// RltXPointRef (thesis 4.4.3.5): one RltPlane's membership of one RltXPoint, with
// the plane's place in that group's relative map.

#include "relslam/core/planar_pose.hpp"
#include "relslam/plane/compare_result.hpp"
#include "relslam/plane/ids.hpp"
#include "relslam/plane/plane_object.hpp"
#include "relslam/plane/rlt_interval.hpp"

#include <optional>

namespace relslam::plane {

// Written by RltXPoint::compute (ComputeXPoint), read by RltMapBuilder. Part 2 adds the
// confirmation flag (Rules 31/32), the reserve copies (Rule 36) and the static-end flag.
struct RltXPointRef {
  XPointId xpoint = kNone;
  // False until a comparison placed the plane (or when its comparison interval is empty).
  bool valid = false;
  // x_T_plane: the plane's reference point — its midpoint at max_length, anchored on key_point
  // — and direction in the group's frame (thesis 4.3.6).
  PlanarPose pose;
  RltInterval interval;  // first and last iteration of the comparison that placed it
  int samples = 0;       // iterations that comparison averaged
  KeyPoint key_point = KeyPoint::None;
  // Part 2: the plane kept its size in the comparison that gave max_length (thesis 4.3.4), so it
  // needs no key point to be placed at that size.
  bool size_static = false;
  double max_length = 0;
  double height = 0;
  int join_iteration = 0;  // when the plane joined the group [R: roll-back, Rule 33]
  // Written by a motion model (Rule 23): its key point is the end that never moved over the whole
  // track, not one that is in view at each of its iterations, so the pose (Rule 16) does not
  // grow an observation from it [C].
  bool tracked = false;
  // Rule 36 (thesis 4.3.7.3): the best comparison so far of this plane (second side) with its chain
  // parent `reserve_partner` (first side) — the partner's size and key point at that time
  // included, so Rule 28's size correction stays right when it is used. Cleared when the chain
  // gives the plane another parent (Rule 30).
  std::optional<CompareResult> reserve;
  PlaneId reserve_partner = kNone;
  // Rules 31/32 (CheckIntervalSize): the comparison placing the plane reached the minimum
  // interval, so it is not checked again ...
  bool confirmed = false;
  // ... or it did not in time and a hint was sent back (Rule 34); still here only when that
  // roll-back was refused, and then not checked again either.
  bool hinted = false;
};

// thesis 4.3.7.3, the test Rules 35 and 36 share: a result replaces a saved one when it is larger by
// more than `same_length` (τ_len), or about as large (within τ_len) and over at least as many
// iterations. Lengths are one plane's (Rule 36) or a group's total (Rule 35).
bool replaces_saved(double length, long long samples, double saved_length, long long saved_samples,
                    double same_length);

// Rule 36, DoBackupCheck (thesis 4.4.3.5; thesis 4.3.7.3), after each comparison of `ref`'s plane (the
// second side of `current`) with its chain parent `partner` (the first side): a reserve the
// current result does not replace — bigger by more than τ_len, or about as big over more
// iterations — or any reserve when the current result cannot place the plane (no comparison, a
// Rule 15 tie, an end without a key point), is copied into `current`, the partner's size and key
// point of that time with it. Otherwise a result that places the plane becomes the reserve. True
// when the reserve was used.
bool do_backup_check(RltXPointRef& ref, PlaneId partner, CompareResult& current, double same_length);

// A comparison that places both planes: made, no Rule 15 tie, and each plane has a key point or
// kept its size (what Rule 30 weighs and Rule 36 keeps).
bool places_both(const CompareResult& result);

}  // namespace relslam::plane
