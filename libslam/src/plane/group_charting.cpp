// The current group (thesis 4.3.5, 4.3.6, walkthrough 4.5): Rule 22's chart of the planes in view
// per group, Rule 29's return to a group that holds every plane in view, and Rule 37's duplicate
// groups (MendMergeAfterLoopClosing: one-way links to the group holding a duplicate of a wall,
// thesis Fig 101).

#include "relslam/plane/rlt_xpoints_s.hpp"

#include <algorithm>
#include <span>
#include <vector>

namespace relslam::plane {

void RltXPointsS::fill_chart(bool oneway_links) {
  // RltXPointChart's counts: per group (motion models aside), the planes in view it holds.
  chart_.assign(xpoints_.size(), 0);
  for (PlaneId p : assignment_) {
    for (const RltXPointRef& ref : planes_[p].refs())
      if (!xpoints_[ref.xpoint].motion_model()) ++chart_[ref.xpoint];
    if (!oneway_links) continue;
    for (XPointId y : planes_[p].oneway_xpoints())    // Rule 37: as if merged with its duplicates
      if (planes_[p].ref(y) == nullptr) ++chart_[y];  // (unless it has since joined that group)
  }
}

void RltXPointsS::chart_current_group() {
  // RltXPointChart::GetBestXPoint (Rule 22, spec §5.5.6): the group holding most of the planes
  // seen this iteration; a tie keeps the current group, other ties the lowest id [R]. A motion
  // model stays current until it ends (Rules 26, 29).
  if (motion_model_active_ || xpoints_.empty()) return;
  fill_chart(true);
  XPointId best = current_;
  int best_count = current_ != kNone ? chart_[current_] : 0;
  for (XPointId x = 0; x < static_cast<XPointId>(xpoints_.size()); ++x)
    if (chart_[x] > best_count) {
      best = x;
      best_count = chart_[x];
    }
  if (best != current_) set_current(best);
}

void RltXPointsS::set_current(XPointId x) {
  // A motion model lasts while its group is the current one (spec §5.10.4).
  if (motion_model_active_ && x != motion_models_.back().xpoint()) {
    motion_model_active_ = false;
    motion_models_.back().end(iteration_);
  }
  current_ = x;
}

bool RltXPointsS::switch_to_group_holding_all(std::span<const DuplicateGroup> through) {
  // Rule 29 (CheckForLoopClosing, spec §5.5.5): with two or more planes in view, a group that
  // holds every one of them becomes current — itself, or (Rule 37's count) through a duplicate
  // listed in `through`; the lowest id wins a tie [R].
  if (stamped_.size() < 2) return false;
  const auto holds = [&](const RltXPoint& x, PlaneId p) {
    return planes_[p].ref(x.id()) != nullptr ||
           std::ranges::any_of(through, [&](const DuplicateGroup& d) { return d.plane == p && d.xpoint == x.id(); });
  };
  for (const RltXPoint& x : xpoints_) {
    if (x.motion_model()) continue;
    if (std::ranges::all_of(assignment_, [&](PlaneId p) { return holds(x, p); })) {
      set_current(x.id());
      return true;
    }
  }
  return false;
}

std::vector<RltXPointsS::DuplicateGroup> RltXPointsS::find_duplicate_groups(const PlanarPose& world_T_robot) {
  // MatchPlanetoMap's all-matches form (spec §5.5.5): every plane in view against the whole map
  // from `world_T_robot`; a match other than the plane itself is a duplicate of its wall, and
  // each group (motion models aside) holding the duplicate is listed with the plane.
  std::vector<DuplicateGroup> out;
  const std::vector<char> none(planes_.size(), 0);
  for (int i = 0; i < static_cast<int>(stamped_.size()); ++i) {
    const PlaneId p = assignment_[i];
    matches_.clear();
    builder_.match_plane_to_map(i, stamped_[i], world_T_robot, options_.global_match, options_.rules.normal_direction,
                                none, matches_);
    for (const PlaneMatch& m : matches_) {
      if (m.plane == p) continue;
      for (const RltXPointRef& ref : planes_[m.plane].refs())
        if (!xpoints_[ref.xpoint].motion_model()) out.push_back({p, ref.xpoint});
    }
  }
  return out;
}

int RltXPointsS::mend_merge_after_loop_closing(std::span<const DuplicateGroup> duplicates) {
  // MendMergeAfterLoopClosing (Rule 37, spec §5.5.5): each group holding a duplicate of a plane
  // in view (find_duplicate_groups) that does not hold the plane gets a one-way link from it. The
  // groups' plane lists are not touched: ComputeXPoint never compares through such a link.
  int added = 0;
  for (const DuplicateGroup& d : duplicates) added += planes_[d.plane].add_oneway(d.xpoint);
  return added;
}

}  // namespace relslam::plane
