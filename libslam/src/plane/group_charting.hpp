#pragma once
// Internal to libslam/plane: the current-group stage (group_charting.cpp) as free functions on
// the algorithm's state (thesis 4.3.5, 4.3.6: Rules 22, 29, 37). Each reads only what it is
// given: the state, this iteration's planes in view, and the options it needs.

#include "relslam/plane/ids.hpp"
#include "relslam/plane/options.hpp"
#include "relslam/plane/rlt_map_builder.hpp"
#include "relslam/plane/rlt_xpoints_state.hpp"

#include <span>
#include <vector>

namespace relslam::plane {

// This iteration's observations (stamped with it) and the RltPlane each was registered to, in
// input order; both the same length.
struct PlanesInView {
  std::span<const PlaneObject> observations;
  std::span<const PlaneId> assignment;
};

// What Rule 37's duplicate search reads of RelativePlaneOptions: the map matching bounds
// (Rule 11) and Rule 10's switch.
struct DuplicateSearchOptions {
  const MatchBounds& global_match;
  bool normal_direction;
  static DuplicateSearchOptions of(const RelativePlaneOptions& o) { return {o.global_match, o.rules.normal_direction}; }
};

// A plane in view and a group holding a duplicate of it (Rule 37).
struct DuplicateGroup {
  PlaneId plane;
  XPointId xpoint;
};

// RltXPointChart's counts into `chart`: per group (motion models aside), the planes in view it
// holds; with `oneway_links` also through Rule 37's one-way links.
void fill_chart(const RltXPointsState& s, std::span<const PlaneId> assignment, bool oneway_links,
                std::vector<int>& chart);
// Rule 22 (GetBestXPoint): the group holding most planes in view becomes current.
void chart_current_group(RltXPointsState& s, std::span<const PlaneId> assignment, std::vector<int>& chart);
// Makes `x` the current group, ending an active motion model of another group.
void set_current(RltXPointsState& s, XPointId x);
// Rule 29: a group holding every plane in view (itself or through `through`) becomes current.
bool switch_to_group_holding_all(RltXPointsState& s, std::span<const PlaneId> assignment,
                                 std::span<const DuplicateGroup> through = {});
// Rule 37: the groups holding a duplicate of a plane in view, matched from `world_T_robot`.
// `matches` is scratch.
std::vector<DuplicateGroup> find_duplicate_groups(const RltXPointsState& s, PlanesInView in_view,
                                                  const PlanarPose& world_T_robot,
                                                  const DuplicateSearchOptions& options,
                                                  std::vector<PlaneMatch>& matches);
// MendMergeAfterLoopClosing (Rule 37): one-way links to the duplicates' groups; how many were new.
int mend_merge_after_loop_closing(RltXPointsState& s, std::span<const DuplicateGroup> duplicates);

}  // namespace relslam::plane
