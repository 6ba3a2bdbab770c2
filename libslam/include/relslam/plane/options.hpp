#pragma once
// Every constant of the Relative Plane algorithm (thesis Chapter 4), with its default and its
// source. Tags: [T] thesis-stated, [P] companion paper, [R] reconstructed/recommended by
// ../shared/specs/relative_plane_em.md §5.14 (the thesis gives almost no numbers), [C] chosen
// here. Part 1 of the algorithm: Rules 1–12, planes reported at full size.

#include "relslam/core/option_issue.hpp"
#include "relslam/plane/plane_object.hpp"

#include <vector>

namespace relslam::plane {

// Which iterations a pair of planes is compared over (thesis 4.3.3, Figs 74/75).
enum class IntervalMode : unsigned char {
  Pair,   // both planes seen: the thesis's final choice (GetCombinedInterval) [T]
  Group,  // ... and inside the group's common interval: less map noise, but can be very short
};

// One switch per rule the thesis turns on or off, for the ablations of spec §6. Each comment
// says what "off" does. Rules 2, 5 and 6 have no switch: Rule 2 is a property the chaining
// has, and Rules 5 and 6 are what the algorithm outputs (pose; map from groups and links).
struct RuleSwitches {
  // Rule 1: register an observation against each RltPlane's previous observation. Off: mapped
  // RltPlanes are registered through the pose only (global matching), as the failed
  // algorithms of thesis 3.6 did; RltPlanes not yet on the map still match locally.
  bool local_registration = true;
  // Rule 3: turn both planes so the first lies at 0° before taking the offset. Off: the raw
  // midpoint difference, translation- but not rotation-invariant (Fig 66).
  bool rotate_to_first = true;
  // Rule 4: align the map with the first observations and the start pose. Off: the map stays
  // in the frame of X0's base plane.
  bool anchor_first_observation = true;
  // Rule 7: a plane joins a group only if it was seen with all its planes for min_common
  // iterations. Off: it joins the working group regardless (its comparison may then be empty).
  bool common_interval = true;
  // Rule 8: two linking planes per new group, their offsets averaged. Off: one is enough.
  bool two_linking_planes = true;
  // Rule 9: prefer the linking planes first seen latest. Off: the earliest first.
  bool latest_linking_planes = true;
  // Rule 10: a plane matches only with its normal facing the same way. Off: a flipped normal
  // matches too (the edge-on wall of Fig 72 then gives two robot poses).
  bool normal_direction = true;
  // Rule 11: an observation no RltPlane takes is placed with the previous pose and matched
  // against the map (backtracking, loop closing). Off: it always starts a new RltPlane.
  bool global_matching = true;
  // Rule 12: a new group links to the first suitable group of a traversal of the whole group
  // graph from the working group. Off: only the working group is tried.
  bool traverse_to_link = true;
};

struct RelativePlaneOptions {
  // Rule 1 registration bounds [R].
  MatchBounds local_match;
  // Rule 11 bounds, looser: the pose may be a little off [R].
  MatchBounds global_match = global_match_defaults();
  // Observations kept per RltPlane: the circular array of thesis 4.4.3.4; 1200 in the runs of
  // Figs 98–99 [T]. Comparisons only see what is still stored.
  int plane_capacity = 1200;
  // An unassigned RltPlane is grouped once it has this many observations [R, spec §5.14].
  int min_readings = 5;
  // Unassigned-list upkeep [P concept, R values]: a plane unseen for more than unseen_drop
  // iterations, or still below min_readings unassigned_drop iterations after it was created,
  // leaves the list (and never gets onto the map).
  int unseen_drop = 10;
  int unassigned_drop = 60;
  // Rule 7: iterations a plane must share with a group's common interval to join it; also the
  // shared iterations a linking plane needs with the new plane [R, n_common].
  int min_common = 5;
  // Linking planes (Rules 8, 9) must have been seen within this many iterations, so old
  // co-visibility does not count [R, W_link].
  int link_window = 10;
  // Two lengths within this are the same size (full-size observations; Rule 16 grows the
  // others in part 2) [R, τ_len].
  double same_length = 0.02;
  // Iterations a pair is compared over (Figs 74/75) [T: Pair].
  IntervalMode interval_mode = IntervalMode::Pair;
  RuleSwitches rules;
};

// Every violated constraint, fields named as in the struct ("local_match.box_margin").
std::vector<OptionIssue> check(const RelativePlaneOptions& options);

}  // namespace relslam::plane
