// Group management, the ManageXPoints part of an iteration (thesis 4.3.2–4.3.5, walkthrough 4.5):
// the first group (bootstrap), Rule 7 (a ready plane joins the working group or a neighbour),
// Rules 8, 9 and 12 (a new group linked through planes seen with the new one, found by
// traversing the groups), Rule 21 (re-acquired planes regrouped) and the unassigned list's
// upkeep.

#include "group_management.hpp"

#include "group_charting.hpp"
#include "motion_model_control.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace relslam::plane {

GroupManagement::GroupManagement(RltXPointsState& state, RltXPointsScratch& scratch, const RltTemporalHints& hints,
                                 const GroupingOptions& options)
    : state_(state), scratch_(scratch), hints_(hints), options_(options) {}

bool GroupManagement::may_join(PlaneId plane, XPointId x) const {
  return hints_.may_join(state_.identity(plane), state_.iteration_, x);
}

void GroupManagement::manage_xpoints(RelativePlaneStep& result) {
  // Rule 29 (thesis 4.3.6): leaving a motion model where a group already holds every plane in
  // view goes back to that group instead of starting a new one.
  if (state_.motion_model_active_ && options_.rules.return_to_visited_group) {
    const bool pseudo_merge = options_.key_points && options_.rules.pseudo_merge;
    bool returned = switch_to_group_holding_all(state_, scratch_.assignment_);
    if (pseudo_merge && scratch_.stamped_.size() >= 2) {
      // Rule 37 looks for duplicates where the motion model puts the robot now. A copy tracks
      // this iteration and the membership it writes is put back: the model and its plane stay
      // exactly as they were, so the rule changes nothing but the chart.
      RltXMMPoint tracking = state_.motion_models_.back();
      RltXPointRef& tracked_ref = *state_.planes_[tracking.plane()].ref(tracking.xpoint());
      const RltXPointRef kept = tracked_ref;
      tracking.compute(state_.planes_, options_.motion_model);
      tracked_ref = kept;
      const PlanarPose world_T_robot =
          tracking.world_T_robot(state_.iteration_).value_or(state_.last_valid_pose_.world_T_robot);
      // CheckForLoopClosing (thesis 4.3.6) counts a group as holding a plane in view through the
      // plane's duplicates too: a wall seen again after the motion model as a new plane (Fig
      // 101's plane 8 ≡ 2) still lets the robot return to the group of the old one.
      const std::vector<DuplicateGroup> duplicates = find_duplicate_groups(
          state_, {scratch_.stamped_, scratch_.assignment_}, world_T_robot, options_.duplicates, scratch_.matches_);
      if (!returned) returned = switch_to_group_holding_all(state_, scratch_.assignment_, duplicates);
      if (returned) result.oneway_links += mend_merge_after_loop_closing(state_, duplicates);
    }
  }
  // Thesis 4.4.3.5, with a bootstrap: the first group waits for two planes.
  if (state_.xpoints_.empty()) bootstrap(result);
  if (!state_.xpoints_.empty()) {
    std::size_t kept = 0;
    for (PlaneId q : state_.unassigned_) {
      const bool grouped =
          state_.planes_[q].readings() >= options_.min_readings && (join_group(q) || make_new_xpoint(q, result));
      if (grouped)
        ++result.planes_grouped;
      else
        state_.unassigned_[kept++] = q;
    }
    state_.unassigned_.resize(kept);
  }
  // Step B: the planes global matching re-acquired (Rule 21).
  if (options_.key_points && options_.rules.regroup_reacquired && !state_.xpoints_.empty()) regroup_reacquired(result);
  if (options_.key_points && options_.rules.regroup_unplaced && !state_.xpoints_.empty()) regroup_unplaced(result);
  if (state_.motion_model_active_ && options_.key_points && options_.rules.return_to_visited_group &&
      options_.rules.current_group_chart)
    end_motion_model_on_the_map(state_, scratch_.assignment_, scratch_.chart_);
  upkeep_unassigned();
  // Step D: the current group by charting (Rule 22); off, the group last started stays current,
  // as before Rule 22 in the thesis (4.3.5).
  if (options_.key_points && options_.rules.current_group_chart)
    chart_current_group(state_, scratch_.assignment_, scratch_.chart_);
}

void GroupManagement::regroup_reacquired(RelativePlaneStep& result) {
  // Rule 21 (thesis 4.3.5). A re-acquired plane shares no recent iterations with any group yet,
  // so it waits, like an unassigned plane, until Rule 7 or linking can take it [R]: it leaves
  // the list when grouped, unseen for unseen_drop iterations, or after unassigned_drop.
  for (PlaneId g : scratch_.reacquired_now_)
    if (std::ranges::none_of(state_.reacquired_, [&](const auto& r) { return r.first == g; }))
      state_.reacquired_.emplace_back(g, state_.iteration_);
  std::erase_if(state_.reacquired_, [&](const std::pair<PlaneId, int>& r) {
    const auto [g, since] = r;
    const RltPlane& plane = state_.planes_[g];
    if (state_.iteration_ - plane.last_iteration() > options_.unseen_drop ||
        state_.iteration_ - since > options_.unassigned_drop)
      return true;
    if (state_.current_ != kNone && plane.ref(state_.current_) != nullptr) return true;  // already where it is seen
    const bool may_start = static_cast<int>(plane.refs().size()) < options_.regroup_memberships;
    const bool grouped = options_.rule21_order == Rule21Order::Walkthrough
                             ? join_group(g) || (may_start && make_new_xpoint(g, result))
                             : (may_start && make_new_xpoint(g, result)) || join_group(g);
    if (grouped) ++result.planes_grouped;
    return grouped || !may_start;
  });
}

void GroupManagement::regroup_unplaced(RelativePlaneStep& result) {
  // Rule 19 extended [C] (options.hpp): a plane in view that is in groups but on no map entry
  // (last iteration's BuildMap), settled there for unplaced_wait iterations, tries Rule 7 in the
  // current group and its neighbours — new partners, a fresh comparison, a key point.
  const std::vector<MapPlane>& map = state_.builder_.map();
  for (PlaneId p : scratch_.assignment_) {
    const RltPlane& plane = state_.planes_[p];
    if (plane.refs().empty() || static_cast<int>(plane.refs().size()) >= options_.regroup_memberships) continue;
    if (p < static_cast<PlaneId>(map.size()) && map[p].group_placed()) continue;
    const bool settled = std::ranges::all_of(plane.refs(), [&](const RltXPointRef& ref) {
      return state_.iteration_ - ref.join_iteration >= options_.unplaced_wait;
    });
    if (settled && join_group(p)) ++result.planes_grouped;
  }
}

bool GroupManagement::bootstrap(RelativePlaneStep& result) {
  // X0: the ready unassigned planes, in creation order, that share min_common iterations.
  scratch_.candidates_.clear();
  RltPlaneInterval shared, narrowed;
  const XPointId x0 = static_cast<XPointId>(state_.xpoints_.size());
  for (PlaneId q : state_.unassigned_) {
    if (state_.planes_[q].readings() < options_.min_readings || !may_join(q, x0)) continue;  // Rule 32's hints
    if (!scratch_.candidates_.empty()) {
      if (RltPlaneInterval::common_size(shared, state_.planes_[q].intervals()) < options_.min_common) continue;
      // Beyond the thesis (open_cut_ends): Rule 4 anchors the whole map on X0, so X0 takes
      // only planes its base can place — a pair of ends seen uncut together (a plane seen cut at
      // both ends, or only ever with cut partners, would leave X0 unplaced for good).
      if (options_.anchor_compare &&
          !compare_with_key_points(state_.planes_[scratch_.candidates_.front()].view(), state_.planes_[q].view(),
                                   *options_.anchor_compare)
               .valid)
        continue;
      RltPlaneInterval::minimum_interval(shared, state_.planes_[q].intervals(), narrowed);
      std::swap(shared, narrowed);
    } else {
      shared = state_.planes_[q].intervals();
    }
    scratch_.candidates_.push_back(q);
  }
  if (scratch_.candidates_.size() < 2) return false;
  create_xpoint(scratch_.candidates_, kNone, {}, kNone);
  std::erase_if(state_.unassigned_,
                [&](PlaneId q) { return std::ranges::find(scratch_.candidates_, q) != scratch_.candidates_.end(); });
  ++result.groups_created;
  result.planes_grouped += static_cast<int>(scratch_.candidates_.size());
  return true;
}

bool GroupManagement::join_group(PlaneId plane) {
  if (state_.current_ == kNone) return false;
  // Rule 7 in the working group, then in its neighbours (thesis 4.3.2 A).
  // A motion-model group never takes a plane (thesis 4.3.2).
  const auto fits = [&](XPointId x) {
    if (state_.xpoints_[x].motion_model() || state_.planes_[plane].ref(x) != nullptr || !may_join(plane, x))
      return false;
    return !options_.rules.common_interval ||
           state_.xpoints_[x].can_add(state_.planes_, state_.planes_[plane], options_.min_common);
  };
  XPointId target = fits(state_.current_) ? state_.current_ : kNone;
  for (std::size_t k = 0; target == kNone && k < state_.xpoints_[state_.current_].adjacent().size(); ++k)
    if (fits(state_.xpoints_[state_.current_].adjacent()[k])) target = state_.xpoints_[state_.current_].adjacent()[k];
  if (target == kNone) return false;
  state_.xpoints_[target].add_plane(state_.planes_, plane, state_.iteration_);
  return true;
}

bool GroupManagement::make_new_xpoint(PlaneId plane, RelativePlaneStep& result) {
  // TraverseToLink (Rule 12): depth first over every group from the working one, each visited
  // once; the first that can give linking planes is linked to. CanMakeNewXPoint (Rule 32).
  if (!hints_.may_start_group(state_.identity(plane), state_.iteration_)) return false;
  scratch_.visited_.assign(state_.xpoints_.size(), 0);
  scratch_.stack_.assign(1, state_.current_);
  std::vector<PlaneId> linking;
  while (!scratch_.stack_.empty()) {
    const XPointId x = scratch_.stack_.back();
    scratch_.stack_.pop_back();
    if (scratch_.visited_[x]) continue;
    scratch_.visited_[x] = 1;
    if (link_to_new_xpoint(x, plane, linking)) {
      std::vector<PlaneId> chain = linking;
      chain.push_back(plane);
      std::ranges::sort(chain);  // creation order (thesis 4.3.2)
      set_current(state_, create_xpoint(std::move(chain), x, std::move(linking), plane));
      ++result.groups_created;
      return true;
    }
    if (!options_.rules.traverse_to_link) break;
    const std::vector<XPointId>& next = state_.xpoints_[x].adjacent();
    scratch_.stack_.insert(scratch_.stack_.end(), next.rbegin(), next.rend());
  }
  return false;  // retried next iteration
}

bool GroupManagement::link_to_new_xpoint(XPointId from, PlaneId plane, std::vector<PlaneId>& linking) {
  // LinkToNewXPoint (Rules 8, 9): planes of `from` placed in it and seen recently together
  // with the new plane.
  const RltPlane& q = state_.planes_[plane];
  const XPointId made = static_cast<XPointId>(state_.xpoints_.size());  // the group the links would join
  scratch_.candidates_.clear();
  for (PlaneId l : state_.xpoints_[from].planes()) {
    const RltPlane& link = state_.planes_[l];
    if (l == plane || !link.ref(from)->valid || state_.iteration_ - link.last_iteration() > options_.link_window)
      continue;
    if (!may_join(l, made)) continue;  // Rule 32's hints hold for linking planes too
    if (RltPlaneInterval::common_size(link.intervals(), q.intervals()) >= options_.min_common)
      scratch_.candidates_.push_back(l);
  }
  // Rule 9: latest first seen first (off: earliest); creation order breaks ties.
  const bool latest = options_.rules.latest_linking_planes;
  std::ranges::sort(scratch_.candidates_, [&](PlaneId x, PlaneId y) {
    const int cx = state_.planes_[x].created_iteration(), cy = state_.planes_[y].created_iteration();
    if (cx != cy) return latest ? cx > cy : cx < cy;
    return x < y;
  });
  linking.clear();
  if (scratch_.candidates_.empty()) return false;
  // A motion-model group links through its one plane (thesis 4.3.2, special case) [T].
  if (!options_.rules.two_linking_planes || state_.xpoints_[from].motion_model()) {
    linking.push_back(scratch_.candidates_.front());
    return true;
  }
  // Rule 8: a second plane seen with both; among the equally recent ones the farthest from the
  // first, for a better-conditioned average (the thesis's "distance").
  for (std::size_t a = 0; a + 1 < scratch_.candidates_.size(); ++a) {
    const RltPlane& first = state_.planes_[scratch_.candidates_[a]];
    RltPlaneInterval::minimum_interval(first.intervals(), q.intervals(), scratch_.scratch_interval_);
    PlaneId best = kNone;
    double best_distance = -1;
    for (std::size_t b = a + 1; b < scratch_.candidates_.size(); ++b) {
      const RltPlane& second = state_.planes_[scratch_.candidates_[b]];
      if (best != kNone && second.created_iteration() != state_.planes_[best].created_iteration()) break;
      if (RltPlaneInterval::common_size(scratch_.scratch_interval_, second.intervals()) < options_.min_common) continue;
      const double distance = (second.ref(from)->pose.translation - first.ref(from)->pose.translation).norm();
      if (distance > best_distance) {
        best = scratch_.candidates_[b];
        best_distance = distance;
      }
    }
    if (best != kNone) {
      linking = {scratch_.candidates_[a], best};
      return true;
    }
  }
  return false;
}

XPointId GroupManagement::create_xpoint(std::vector<PlaneId> chain, XPointId from, std::vector<PlaneId> linking,
                                        PlaneId founder) {
  const XPointId id = static_cast<XPointId>(state_.xpoints_.size());
  state_.founders_.push_back(founder);
  if (options_.chain_order == ChainOrder::Reversed) std::ranges::reverse(chain);  // E31 only
  for (PlaneId p : chain) state_.planes_[p].join(id, state_.iteration_);
  state_.xpoints_.emplace_back(id, state_.iteration_, std::move(chain));
  state_.links_.push_back({from, id, std::move(linking), from == kNone, state_.iteration_});
  if (from != kNone) {
    state_.xpoints_[from].add_adjacent(id);
    state_.xpoints_[id].add_adjacent(from);
  }
  if (state_.current_ == kNone) state_.current_ = id;
  return id;
}

void GroupManagement::upkeep_unassigned() {
  // thesis 4.3.2 C [P]: planes that left the view, or were seen too rarely, leave the list.
  std::erase_if(state_.unassigned_, [&](PlaneId q) {
    const RltPlane& p = state_.planes_[q];
    return state_.iteration_ - p.last_iteration() > options_.unseen_drop ||
           (p.readings() < options_.min_readings &&
            state_.iteration_ - p.created_iteration() > options_.unassigned_drop);
  });
}

}  // namespace relslam::plane
