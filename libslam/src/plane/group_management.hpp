#pragma once
// Internal to libslam/plane: the group-management stage (group_management.cpp, ManageXPoints:
// thesis 4.3.2–4.3.5; Rules 7–9, 12, 21, with Rule 29's return and Rule 37's duplicates) as a
// small class over the algorithm's state, its per-iteration scratch, the hints (Rule 32) and
// the options it reads.

#include "relslam/plane/hints.hpp"
#include "relslam/plane/key_point_compare.hpp"
#include "relslam/plane/ids.hpp"
#include "relslam/plane/options.hpp"
#include "relslam/plane/relative_plane_step.hpp"
#include "relslam/plane/rlt_xpoints_scratch.hpp"
#include "relslam/plane/rlt_xpoints_state.hpp"

#include "group_charting.hpp"

#include <optional>
#include <span>
#include <vector>

namespace relslam::plane {

// What ManageXPoints reads of RelativePlaneOptions: the grouping thresholds, the rule switches,
// the motion model's tracking (Rule 37 looks where it puts the robot) and Rule 37's map
// matching.
struct GroupingOptions {
  int min_readings;
  int min_common;
  int link_window;
  int unseen_drop;
  int unassigned_drop;
  int regroup_memberships;
  int unplaced_wait;
  Rule21Order rule21_order;
  ChainOrder chain_order;
  bool key_points;
  const RuleSwitches& rules;
  const MotionModelOptions& motion_model;
  // open_cut_ends: X0's planes must compare on ends the sensor saw as the walls' own.
  std::optional<ComparePlanesOptions> anchor_compare;
  DuplicateSearchOptions duplicates;
  static GroupingOptions of(const RelativePlaneOptions& o) {
    return {o.min_readings,
            o.min_common,
            o.link_window,
            o.unseen_drop,
            o.unassigned_drop,
            o.regroup_memberships,
            o.unplaced_wait,
            o.rule21_order,
            o.chain_order,
            o.key_points,
            o.rules,
            o.motion_model,
            cut_ends_open(o) ? std::optional<ComparePlanesOptions>(o) : std::nullopt,
            DuplicateSearchOptions::of(o)};
  }
};

// One iteration's ManageXPoints: construct over the state and call manage_xpoints once.
class GroupManagement {
 public:
  GroupManagement(RltXPointsState& state, RltXPointsScratch& scratch, const RltTemporalHints& hints,
                  const GroupingOptions& options);
  // Steps A (Rule 7, linking, the first group), B (Rule 21), C (the list's upkeep) and D (Rule 22).
  void manage_xpoints(RelativePlaneStep& result);

 private:
  bool may_join(PlaneId plane, XPointId x) const;  // Rule 32's hints
  bool bootstrap(RelativePlaneStep& result);
  bool join_group(PlaneId plane);
  bool make_new_xpoint(PlaneId plane, RelativePlaneStep& result);
  bool link_to_new_xpoint(XPointId from, PlaneId plane, std::vector<PlaneId>& linking);
  XPointId create_xpoint(std::vector<PlaneId> chain, XPointId from, std::vector<PlaneId> linking, PlaneId founder);
  void upkeep_unassigned();
  void regroup_reacquired(RelativePlaneStep& result);
  void regroup_unplaced(RelativePlaneStep& result);

  RltXPointsState& state_;
  RltXPointsScratch& scratch_;
  const RltTemporalHints& hints_;
  GroupingOptions options_;
};

}  // namespace relslam::plane
