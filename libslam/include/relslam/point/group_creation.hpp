#pragma once
// Group creation (thesis 6.4, the algorithm of 6.4.3; levels and clean-up 6.5.5,
// 5.12): turning ready ungrouped RltPoints into RltGroups on the map. Eigen only.

#include "relslam/point/group_planning.hpp"
#include "relslam/point/options.hpp"
#include "relslam/point/rlt_map.hpp"

#include <deque>
#include <vector>

namespace relslam::point {

// What one iteration's group creation did, for StepResult.
struct CreationReport {
  int groups_created = 0;
  int dynamic_flagged = 0;  // points RltBinning flagged
  int binning_comparisons = 0;
  double binning_ms = 0;  // wall time of RltBinning (thesis Fig 117)
};

// Carries across iterations what group creation waits on: the level-3 candidates and the
// temporary groups to review. The ungrouped lists of the other levels live in the map, since
// matching and merging edit them too.
class GroupCreation {
 public:
  // A new RltPoint: with level 3 on it waits to leave the view (thesis 6.5.5).
  void add_point(PointId id, const PointSlamOptions& options);

  // Thesis 6.4.3 at iteration k: for the temporary, then the final level, every entry of the
  // level's RltUngroupedList whose look-ahead has passed is planned (GroupPlanner) and, if a
  // plan results, built; then level 3 for the points that left the view. Points RltBinning
  // finds moving are flagged dynamic either way.
  CreationReport create_groups(RltMap& map, int k, const PointSlamOptions& options);

  // Thesis 6.5.5: temporary groups, once their new members have had the final look-ahead to be
  // taken by final groups, are retired if they own none of them (they map nothing).
  void retire_redundant_temporary_groups(RltMap& map, int k, const PointSlamOptions& options);

 private:
  bool try_create(RltMap& map, GroupLevel level, const RltUngroupedList::Entry& entry, int k,
                  const PointSlamOptions& options, CreationReport& report);
  void create_level3_groups(RltMap& map, int k, const PointSlamOptions& options, CreationReport& report);
  // Takes in one plan's outcome: its dynamic points are flagged, its group (if any) is built.
  bool apply(RltMap& map, GroupLevel level, int c0, int k, const PlanOutcome& outcome, CreationReport& report);
  // Builds the planned group, hands its new members over (ownership by level, thesis 6.4) and
  // computes it over [c0, k].
  void build_group(RltMap& map, GroupLevel level, int c0, int k, const GroupPlan& plan);

  GroupPlanner planner_;
  std::vector<PointId> level3_waiting_;      // not yet level-3 grouped, creation order
  std::deque<GroupId> temporary_to_review_;  // temporary groups in creation order
};

// The constants of the temporary or the final level.
const GroupLevelOptions& level_options(const PointSlamOptions& options, GroupLevel level);

// Puts `id` in the RltUngroupedList of `level` to wait for grouping from `start`, if that level is on and has not grouped it yet (thesis 6.4.2):
// a new visible run, a moved map frame, the adaptive preset's retry. `restart`: an entry it
// already has starts again at `start` (else it keeps its place).
void wait_for_group(RltMap& map, PointId id, GroupLevel level, int start, const PointSlamOptions& options,
                    bool restart = false);

// Flags a point dynamic (thesis 6.5.3): off the map and out of every ungrouped list, anchor set
// and global match, and every alive group with it in its basis is retired (a moving
// basis point gives the group no consistent frame). It stays locally matchable, so a mover
// keeps one RltPoint. Returns false if it was flagged already.
bool mark_dynamic(RltMap& map, PointId id);

}  // namespace relslam::point
