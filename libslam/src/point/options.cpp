#include "relslam/point/options.hpp"

#include <algorithm>
#include <string>

namespace relslam::point {
namespace {

void check_level(std::vector<OptionIssue>& issues, const std::string& name, const GroupLevelOptions& l) {
  require_at_least(issues, name + ".look_ahead", l.look_ahead, 1);
  require_at_least(issues, name + ".look_back", l.look_back, 0);
  require_at_least(issues, name + ".accuracy_reduction", l.accuracy_reduction, 0);
  require_at_most(issues, name + ".accuracy_reduction", l.accuracy_reduction, l.look_ahead);
  require_at_least(issues, name + ".prev_min", l.prev_min, 3);  // three anchors fix a rigid motion
  require_at_least(issues, name + ".prev_max", l.prev_max, l.prev_min);
  require_at_least(issues, name + ".next_min", l.next_min, 1);
}

}  // namespace

std::vector<OptionIssue> check(const PointSlamOptions& o) {
  std::vector<OptionIssue> issues;
  require_at_least(issues, "match_look_back", o.match_look_back, 1);
  require_above(issues, "local_bound", o.local_bound, 0.0);
  require_above(issues, "compensated_bound", o.compensated_bound, 0.0);
  require_at_most(issues, "compensated_bound", o.compensated_bound, o.local_bound);
  require_above(issues, "motion_outlier_cut", o.motion_outlier_cut, 1.0);
  require_above(issues, "global_bound", o.global_bound, 0.0);
  require_at_least(issues, "local_cell_size", o.local_cell_size, o.local_bound);
  require_at_least(issues, "global_cell_size", o.global_cell_size, std::max(o.global_bound, o.merge_bound));
  if (!o.temporary_group.enabled && !o.final_group.enabled)
    issues.push_back({"final_group.enabled", "temporary and final groups cannot both be off"});
  require_at_least(issues, "level3.gap", o.level3.gap, 0);
  require_at_least(issues, "level3.prev_min", o.level3.prev_min, 3);
  if (o.provisional_root && !o.pose_from_unmapped)
    issues.push_back({"provisional_root", "needs pose_from_unmapped (its groups register to provisional positions)"});
  require_at_least(issues, "octree_cell_size", o.octree_cell_size, o.local_bound);
  require_at_least(issues, "merge_delay", o.merge_delay, 1);
  require_above(issues, "merge_bound", o.merge_bound, 0.0);
  require_at_least(issues, "binning.abs_gap", o.binning.abs_gap, 0.0);
  require_at_least(issues, "binning.rel_gap", o.binning.rel_gap, 0.0);
  require_at_least(issues, "binning.min_pair_samples", o.binning.min_pair_samples, 2);
  require_above(issues, "binning.majority_fraction", o.binning.majority_fraction, 0.0);
  require_at_most(issues, "binning.majority_fraction", o.binning.majority_fraction, 1.0);
  check_level(issues, "temporary_group", o.temporary_group);
  check_level(issues, "final_group", o.final_group);
  require_above(issues, "min_basis_ratio", o.min_basis_ratio, 0.0);
  require_at_least(issues, "temporary_cleanup_period", o.temporary_cleanup_period, 1);
  const int window = std::max(o.final_group.look_back + o.final_group.look_ahead,
                              o.temporary_group.look_back + o.temporary_group.look_ahead) +
                     o.match_look_back + 2;
  require_at_least(issues, "charting_capacity", o.charting_capacity, window);
  require_at_least(issues, "ring_capacity", o.ring_capacity, window);
  return issues;
}

}  // namespace relslam::point
