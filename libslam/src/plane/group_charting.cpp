// The current group (thesis 4.3.5, 4.3.6, walkthrough 4.5): Rule 22's chart of the planes in view
// per group, Rule 29's return to a group that holds every plane in view, and Rule 37's duplicate
// groups (MendMergeAfterLoopClosing: one-way links to the group holding a duplicate of a wall,
// thesis Fig 101).

#include "group_charting.hpp"

#include <algorithm>
#include <span>
#include <vector>

namespace relslam::plane {

void fill_chart(const RltXPointsState& s, std::span<const PlaneId> assignment, bool oneway_links,
                std::vector<int>& chart) {
  // RltXPointChart's counts: per group (motion models aside), the planes in view it holds.
  chart.assign(s.xpoints_.size(), 0);
  for (PlaneId p : assignment) {
    for (const RltXPointRef& ref : s.planes_[p].refs())
      if (!s.xpoints_[ref.xpoint].motion_model()) ++chart[ref.xpoint];
    if (!oneway_links) continue;
    for (XPointId y : s.planes_[p].oneway_xpoints())   // Rule 37: as if merged with its duplicates
      if (s.planes_[p].ref(y) == nullptr) ++chart[y];  // (unless it has since joined that group)
  }
}

void chart_current_group(RltXPointsState& s, std::span<const PlaneId> assignment, std::vector<int>& chart) {
  // RltXPointChart::GetBestXPoint (Rule 22, thesis 4.3.5): the group holding most of the planes
  // seen this iteration; a tie keeps the current group, other ties the lowest id [R]. A motion
  // model stays current until it ends (Rules 26, 29).
  if (s.motion_model_active_ || s.xpoints_.empty()) return;
  fill_chart(s, assignment, true, chart);
  XPointId best = s.current_;
  int best_count = s.current_ != kNone ? chart[s.current_] : 0;
  for (XPointId x = 0; x < static_cast<XPointId>(s.xpoints_.size()); ++x)
    if (chart[x] > best_count) {
      best = x;
      best_count = chart[x];
    }
  if (best != s.current_) set_current(s, best);
}

void set_current(RltXPointsState& s, XPointId x) {
  // A motion model lasts while its group is the current one (thesis 4.3.6).
  if (s.motion_model_active_ && x != s.motion_models_.back().xpoint()) {
    s.motion_model_active_ = false;
    s.motion_models_.back().end(s.iteration_);
  }
  s.current_ = x;
}

bool switch_to_group_holding_all(RltXPointsState& s, std::span<const PlaneId> assignment,
                                 std::span<const DuplicateGroup> through) {
  // Rule 29 (CheckForLoopClosing, thesis 4.3.6): with two or more planes in view, a group that
  // holds every one of them becomes current — itself, or (Rule 37's count) through a duplicate
  // listed in `through`; the lowest id wins a tie [R].
  if (assignment.size() < 2) return false;
  const auto holds = [&](const RltXPoint& x, PlaneId p) {
    return s.planes_[p].ref(x.id()) != nullptr ||
           std::ranges::any_of(through, [&](const DuplicateGroup& d) { return d.plane == p && d.xpoint == x.id(); });
  };
  for (const RltXPoint& x : s.xpoints_) {
    if (x.motion_model()) continue;
    if (std::ranges::all_of(assignment, [&](PlaneId p) { return holds(x, p); })) {
      set_current(s, x.id());
      return true;
    }
  }
  return false;
}

std::vector<DuplicateGroup> find_duplicate_groups(const RltXPointsState& s, PlanesInView in_view,
                                                  const PlanarPose& world_T_robot,
                                                  const DuplicateSearchOptions& options,
                                                  std::vector<PlaneMatch>& matches) {
  // MatchPlanetoMap's all-matches form (thesis 4.3.6): every plane in view against the whole map
  // from `world_T_robot`; a match other than the plane itself is a duplicate of its wall, and
  // each group (motion models aside) holding the duplicate is listed with the plane.
  std::vector<DuplicateGroup> out;
  const std::vector<char> none(s.planes_.size(), 0);
  for (int i = 0; i < static_cast<int>(in_view.observations.size()); ++i) {
    const PlaneId p = in_view.assignment[i];
    matches.clear();
    s.builder_.match_plane_to_map(i, in_view.observations[i], world_T_robot, options.global_match,
                                  options.normal_direction, none, matches);
    for (const PlaneMatch& m : matches) {
      if (m.plane == p) continue;
      for (const RltXPointRef& ref : s.planes_[m.plane].refs())
        if (!s.xpoints_[ref.xpoint].motion_model()) out.push_back({p, ref.xpoint});
    }
  }
  return out;
}

int mend_merge_after_loop_closing(RltXPointsState& s, std::span<const DuplicateGroup> duplicates) {
  // MendMergeAfterLoopClosing (Rule 37, thesis 4.3.6): each group holding a duplicate of a plane
  // in view (find_duplicate_groups) that does not hold the plane gets a one-way link from it. The
  // groups' plane lists are not touched: ComputeXPoint never compares through such a link.
  int added = 0;
  for (const DuplicateGroup& d : duplicates) added += s.planes_[d.plane].add_oneway(d.xpoint);
  return added;
}

}  // namespace relslam::plane
