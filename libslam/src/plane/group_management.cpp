// Group management, the ManageXPoints part of an iteration (thesis 4.3.2–4.3.5, walkthrough 4.5):
// the first group (bootstrap), Rule 7 (a ready plane joins the working group or a neighbour),
// Rules 8, 9 and 12 (a new group linked through planes seen with the new one, found by
// traversing the groups), Rule 21 (re-acquired planes regrouped) and the unassigned list's
// upkeep.

#include "relslam/plane/rlt_xpoints_s.hpp"

#include "group_charting.hpp"
#include "motion_model_control.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace relslam::plane {

void RltXPointsS::manage_xpoints(RelativePlaneStep& result) {
  // Rule 29 (spec §5.10.4): leaving a motion model where a group already holds every plane in
  // view goes back to that group instead of starting a new one.
  if (motion_model_active_ && options_.rules.return_to_visited_group) {
    const bool pseudo_merge = options_.key_points && options_.rules.pseudo_merge;
    bool returned = switch_to_group_holding_all(*this, assignment_);
    if (pseudo_merge && stamped_.size() >= 2) {
      // Rule 37 looks for duplicates where the motion model puts the robot now. A copy tracks
      // this iteration and the membership it writes is put back: the model and its plane stay
      // exactly as they were, so the rule changes nothing but the chart.
      RltXMMPoint tracking = motion_models_.back();
      RltXPointRef& tracked_ref = *planes_[tracking.plane()].ref(tracking.xpoint());
      const RltXPointRef kept = tracked_ref;
      tracking.compute(planes_, options_.motion_model);
      tracked_ref = kept;
      const PlanarPose world_T_robot = tracking.world_T_robot(iteration_).value_or(last_valid_pose_.world_T_robot);
      // CheckForLoopClosing (spec §5.5.5) counts a group as holding a plane in view through the
      // plane's duplicates too: a wall seen again after the motion model as a new plane (Fig
      // 101's plane 8 ≡ 2) still lets the robot return to the group of the old one.
      const std::vector<DuplicateGroup> duplicates = find_duplicate_groups(
          *this, {stamped_, assignment_}, world_T_robot, DuplicateSearchOptions::of(options_), matches_);
      if (!returned) returned = switch_to_group_holding_all(*this, assignment_, duplicates);
      if (returned) result.oneway_links += mend_merge_after_loop_closing(*this, duplicates);
    }
  }
  // Spec §5.5.1 step A, with the bootstrap of A23: the first group waits for two planes.
  if (xpoints_.empty()) bootstrap(result);
  if (!xpoints_.empty()) {
    std::size_t kept = 0;
    for (PlaneId q : unassigned_) {
      const bool grouped =
          planes_[q].readings() >= options_.min_readings && (join_group(q) || make_new_xpoint(q, result));
      if (grouped)
        ++result.planes_grouped;
      else
        unassigned_[kept++] = q;
    }
    unassigned_.resize(kept);
  }
  // Step B: the planes global matching re-acquired (Rule 21).
  if (options_.key_points && options_.rules.regroup_reacquired && !xpoints_.empty()) regroup_reacquired(result);
  if (options_.key_points && options_.rules.regroup_unplaced && !xpoints_.empty()) regroup_unplaced(result);
  if (motion_model_active_ && options_.key_points && options_.rules.return_to_visited_group &&
      options_.rules.current_group_chart)
    end_motion_model_on_the_map(*this, assignment_, chart_);
  upkeep_unassigned();
  // Step D: the current group by charting (Rule 22); off, the group last started stays current,
  // as before Rule 22 in the thesis (4.3.5).
  if (options_.key_points && options_.rules.current_group_chart) chart_current_group(*this, assignment_, chart_);
}

void RltXPointsS::regroup_reacquired(RelativePlaneStep& result) {
  // Rule 21 (spec §5.5.4). A re-acquired plane shares no recent iterations with any group yet,
  // so it waits, like an unassigned plane, until Rule 7 or linking can take it [R]: it leaves
  // the list when grouped, unseen for unseen_drop iterations, or after unassigned_drop.
  for (PlaneId g : reacquired_now_)
    if (std::ranges::none_of(reacquired_, [&](const auto& r) { return r.first == g; }))
      reacquired_.emplace_back(g, iteration_);
  std::erase_if(reacquired_, [&](const std::pair<PlaneId, int>& r) {
    const auto [g, since] = r;
    const RltPlane& plane = planes_[g];
    if (iteration_ - plane.last_iteration() > options_.unseen_drop || iteration_ - since > options_.unassigned_drop)
      return true;
    if (current_ != kNone && plane.ref(current_) != nullptr) return true;  // already where it is seen
    const bool may_start = static_cast<int>(plane.refs().size()) < options_.regroup_memberships;
    const bool grouped = options_.rule21_order == Rule21Order::Walkthrough
                             ? join_group(g) || (may_start && make_new_xpoint(g, result))
                             : (may_start && make_new_xpoint(g, result)) || join_group(g);
    if (grouped) ++result.planes_grouped;
    return grouped || !may_start;
  });
}

void RltXPointsS::regroup_unplaced(RelativePlaneStep& result) {
  // Rule 19 extended [C] (options.hpp): a plane in view that is in groups but on no map entry
  // (last iteration's BuildMap), settled there for unplaced_wait iterations, tries Rule 7 in the
  // current group and its neighbours — new partners, a fresh comparison, a key point.
  const std::vector<MapPlane>& map = builder_.map();
  for (PlaneId p : assignment_) {
    const RltPlane& plane = planes_[p];
    if (plane.refs().empty() || static_cast<int>(plane.refs().size()) >= options_.regroup_memberships) continue;
    if (p < static_cast<PlaneId>(map.size()) && map[p].mapped) continue;
    const bool settled = std::ranges::all_of(plane.refs(), [&](const RltXPointRef& ref) {
      return iteration_ - ref.join_iteration >= options_.unplaced_wait;
    });
    if (settled && join_group(p)) ++result.planes_grouped;
  }
}

bool RltXPointsS::bootstrap(RelativePlaneStep& result) {
  // X0: the ready unassigned planes, in creation order, that share min_common iterations.
  candidates_.clear();
  RltPlaneInterval shared, narrowed;
  const XPointId x0 = static_cast<XPointId>(xpoints_.size());
  for (PlaneId q : unassigned_) {
    if (planes_[q].readings() < options_.min_readings || !may_join(q, x0)) continue;  // Rule 32's hints
    if (!candidates_.empty()) {
      if (RltPlaneInterval::common_size(shared, planes_[q].intervals()) < options_.min_common) continue;
      RltPlaneInterval::minimum_interval(shared, planes_[q].intervals(), narrowed);
      std::swap(shared, narrowed);
    } else {
      shared = planes_[q].intervals();
    }
    candidates_.push_back(q);
  }
  if (candidates_.size() < 2) return false;
  create_xpoint(candidates_, kNone, {}, kNone);
  std::erase_if(unassigned_, [&](PlaneId q) { return std::ranges::find(candidates_, q) != candidates_.end(); });
  ++result.groups_created;
  result.planes_grouped += static_cast<int>(candidates_.size());
  return true;
}

bool RltXPointsS::join_group(PlaneId plane) {
  if (current_ == kNone) return false;
  // Rule 7 in the working group, then in its neighbours (spec §5.5.1 A).
  // A motion-model group never takes a plane (spec §5.5.2).
  const auto fits = [&](XPointId x) {
    if (xpoints_[x].motion_model() || planes_[plane].ref(x) != nullptr || !may_join(plane, x)) return false;
    return !options_.rules.common_interval || xpoints_[x].can_add(planes_, planes_[plane], options_.min_common);
  };
  XPointId target = fits(current_) ? current_ : kNone;
  for (std::size_t k = 0; target == kNone && k < xpoints_[current_].adjacent().size(); ++k)
    if (fits(xpoints_[current_].adjacent()[k])) target = xpoints_[current_].adjacent()[k];
  if (target == kNone) return false;
  xpoints_[target].add_plane(planes_, plane, iteration_);
  return true;
}

bool RltXPointsS::make_new_xpoint(PlaneId plane, RelativePlaneStep& result) {
  // TraverseToLink (Rule 12): depth first over every group from the working one, each visited
  // once; the first that can give linking planes is linked to. CanMakeNewXPoint (Rule 32).
  if (!hints_.may_start_group(identity(plane), iteration_)) return false;
  visited_.assign(xpoints_.size(), 0);
  stack_.assign(1, current_);
  std::vector<PlaneId> linking;
  while (!stack_.empty()) {
    const XPointId x = stack_.back();
    stack_.pop_back();
    if (visited_[x]) continue;
    visited_[x] = 1;
    if (link_to_new_xpoint(x, plane, linking)) {
      std::vector<PlaneId> chain = linking;
      chain.push_back(plane);
      std::ranges::sort(chain);  // creation order (spec §5.5.3)
      set_current(*this, create_xpoint(std::move(chain), x, std::move(linking), plane));
      ++result.groups_created;
      return true;
    }
    if (!options_.rules.traverse_to_link) break;
    const std::vector<XPointId>& next = xpoints_[x].adjacent();
    stack_.insert(stack_.end(), next.rbegin(), next.rend());
  }
  return false;  // retried next iteration (spec A22)
}

bool RltXPointsS::link_to_new_xpoint(XPointId from, PlaneId plane, std::vector<PlaneId>& linking) {
  // LinkToNewXPoint (Rules 8, 9): planes of `from` placed in it and seen recently together
  // with the new plane.
  const RltPlane& q = planes_[plane];
  const XPointId made = static_cast<XPointId>(xpoints_.size());  // the group the links would join
  candidates_.clear();
  for (PlaneId l : xpoints_[from].planes()) {
    const RltPlane& link = planes_[l];
    if (l == plane || !link.ref(from)->valid || iteration_ - link.last_iteration() > options_.link_window) continue;
    if (!may_join(l, made)) continue;  // Rule 32's hints hold for linking planes too
    if (RltPlaneInterval::common_size(link.intervals(), q.intervals()) >= options_.min_common) candidates_.push_back(l);
  }
  // Rule 9: latest first seen first (off: earliest); creation order breaks ties.
  const bool latest = options_.rules.latest_linking_planes;
  std::ranges::sort(candidates_, [&](PlaneId x, PlaneId y) {
    const int cx = planes_[x].created_iteration(), cy = planes_[y].created_iteration();
    if (cx != cy) return latest ? cx > cy : cx < cy;
    return x < y;
  });
  linking.clear();
  if (candidates_.empty()) return false;
  // A motion-model group links through its one plane (spec §5.5.3, special case) [T].
  if (!options_.rules.two_linking_planes || xpoints_[from].motion_model()) {
    linking.push_back(candidates_.front());
    return true;
  }
  // Rule 8: a second plane seen with both; among the equally recent ones the farthest from the
  // first, for a better-conditioned average (spec A21: the thesis's "distance").
  for (std::size_t a = 0; a + 1 < candidates_.size(); ++a) {
    const RltPlane& first = planes_[candidates_[a]];
    RltPlaneInterval::minimum_interval(first.intervals(), q.intervals(), scratch_interval_);
    PlaneId best = kNone;
    double best_distance = -1;
    for (std::size_t b = a + 1; b < candidates_.size(); ++b) {
      const RltPlane& second = planes_[candidates_[b]];
      if (best != kNone && second.created_iteration() != planes_[best].created_iteration()) break;
      if (RltPlaneInterval::common_size(scratch_interval_, second.intervals()) < options_.min_common) continue;
      const double distance = (second.ref(from)->pose.translation - first.ref(from)->pose.translation).norm();
      if (distance > best_distance) {
        best = candidates_[b];
        best_distance = distance;
      }
    }
    if (best != kNone) {
      linking = {candidates_[a], best};
      return true;
    }
  }
  return false;
}

XPointId RltXPointsS::create_xpoint(std::vector<PlaneId> chain, XPointId from, std::vector<PlaneId> linking,
                                    PlaneId founder) {
  const XPointId id = static_cast<XPointId>(xpoints_.size());
  founders_.push_back(founder);
  if (options_.chain_order == ChainOrder::Reversed) std::ranges::reverse(chain);  // E31 only
  for (PlaneId p : chain) planes_[p].join(id, iteration_);
  xpoints_.emplace_back(id, iteration_, std::move(chain));
  links_.push_back({from, id, std::move(linking), from == kNone, iteration_});
  if (from != kNone) {
    xpoints_[from].add_adjacent(id);
    xpoints_[id].add_adjacent(from);
  }
  if (current_ == kNone) current_ = id;
  return id;
}

void RltXPointsS::upkeep_unassigned() {
  // Spec §5.5.1 C [P]: planes that left the view, or were seen too rarely, leave the list.
  std::erase_if(unassigned_, [&](PlaneId q) {
    const RltPlane& p = planes_[q];
    return iteration_ - p.last_iteration() > options_.unseen_drop ||
           (p.readings() < options_.min_readings && iteration_ - p.created_iteration() > options_.unassigned_drop);
  });
}

}  // namespace relslam::plane
