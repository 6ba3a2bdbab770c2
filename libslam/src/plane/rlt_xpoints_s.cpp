#include "relslam/plane/rlt_xpoints_s.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <utility>

namespace relslam::plane {
namespace {

using Clock = std::chrono::steady_clock;

// Milliseconds since `start`, which moves on to now.
double lap(Clock::time_point& start) {
  const Clock::time_point now = Clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - start).count();
  start = now;
  return ms;
}

}  // namespace

RltXPointsS::RltXPointsS(const RelativePlaneOptions& options, const PlanarPose& world_T_start)
    : options_(options), world_T_start_(world_T_start) {
  const std::vector<OptionIssue> issues = check(options);
  if (!issues.empty())
    throw std::logic_error("RltXPointsS: options." + issues.front().field + ": " + issues.front().problem);
}

RelativePlaneStep RltXPointsS::step(const PlaneFrame& frame) {
  if (started_ && frame.iteration <= iteration_)
    throw std::logic_error("RltXPointsS::step: iteration " + std::to_string(frame.iteration) + " after " +
                           std::to_string(iteration_));
  const RollBackOptions& rb = options_.rollback;
  step_log_begin_ = roll_back_log_.size();
  if (keeps_history()) {
    // PlaneRecord (thesis 4.4.3.17): the input is kept for the replay; before the first one the
    // empty state is kept, so a roll-back can reach the start of the run.
    if (storage_.oldest() == nullptr) storage_.checkpoint_if_due(frame.iteration - 1, *this, rb.checkpoint_period);
    storage_.record(frame);
  }
  RelativePlaneStep result = iterate(frame);
  if (rb.force_every > 0 && frame.iteration > 0 && frame.iteration % rb.force_every == 0)
    set_roll_back_to({.iteration_requested = frame.iteration, .target_iteration = frame.iteration - rb.force_depth});
  // Walkthrough 4.5: RollBack is called last, after GetPoset.
  if (roll_back_request_) roll_back(result);
  if (keeps_history()) {
    storage_.checkpoint_if_due(iteration_, *this, rb.checkpoint_period);
    storage_.trim(iteration_, rb.max_depth);
  }

  result.world_T_robot = pose_.world_T_robot;
  result.pose_valid = pose_.valid;
  result.pose_planes = pose_.planes_used;
  result.assignment = assignment_;
  result.map = builder_.map();
  result.groups = xpoints_;
  result.links = links_;
  result.current_group = current_;
  result.motion_model = active_motion_model();
  result.roll_backs = std::span<const RollBackEvent>(roll_back_log_).subspan(step_log_begin_);
  return result;
}

RelativePlaneStep RltXPointsS::iterate(const PlaneFrame& frame) {
  RelativePlaneStep result;
  result.iteration = frame.iteration;
  Clock::time_point t = Clock::now();
  start_iteration(frame.iteration);
  add_planes(frame, result);
  result.timings.add_ms = lap(t);
  manage_xpoints(result);
  result.timings.manage_ms = lap(t);
  compute_xpoints(result);
  result.timings.compute_ms = lap(t);
  builder_.build_map(links_, xpoints_, planes_, world_T_start_, options_);
  result.timings.build_ms = lap(t);
  get_poset();
  result.timings.pose_ms = lap(t);
  return result;
}

void RltXPointsS::request_roll_back(int target) {
  set_roll_back_to({.iteration_requested = iteration_, .target_iteration = target});
}

void RltXPointsS::send_hint(const RltTemporalHint& hint) {
  hints_.add(hint);
  PlaneId plane = kNone;
  for (PlaneId p = 0; p < static_cast<PlaneId>(planes_.size()) && plane == kNone; ++p)
    if (identity(p) == hint.plane) plane = p;
  set_roll_back_to({iteration_, hint.iteration, plane, hint.xpoint, static_cast<int>(hint.level)});
}

void RltXPointsS::set_roll_back_to(const RollBackEvent& request) {
  // SetRollBackTo: several requests in one iteration roll back once, to the earliest target.
  if (!roll_back_request_ || request.target_iteration < roll_back_request_->target_iteration)
    roll_back_request_ = request;
}

void RltXPointsS::check_interval_sizes(const RltXPoint& x, RelativePlaneStep& result) {
  failed_.clear();
  x.check_interval_size(planes_, options_.rollback, iteration_, failed_);
  for (PlaneId p : failed_) {
    RltXPointRef& ref = *planes_[p].ref(x.id());
    ref.hinted = true;
    const PlaneIdentity id = identity(p);
    // Rule 32: the next level for this plane. Thesis 4.5 (CheckIntervalSize): a plane that
    // started the group it fails in "should not be added to any RltXPoint" — its own new group
    // was the second try, and the replay would only make the same group again.
    const int level = founders_[x.id()] == p ? static_cast<int>(HintLevel::NotOnMap)
                                              : std::min(hints_.count_for(id) + 1, static_cast<int>(HintLevel::NotOnMap));
    hints_.add({static_cast<HintLevel>(level), id, ref.join_iteration, x.id()});
    ++result.roll_back.hints;
    // Rule 34: back to when the plane joined, so the hint can act there.
    set_roll_back_to({iteration_, ref.join_iteration, p, x.id(), level});
  }
}

void RltXPointsS::roll_back(RelativePlaneStep& result) {
  // RollBack (Rule 33, spec §5.11.3): restore the end of target − 1 and replay the stored inputs
  // up to now with the hints held; a roll-back asked for while replaying is served after that
  // replayed iteration (nesting), up to rollback.max_nesting in one step.
  const Clock::time_point start = Clock::now();
  const RollBackOptions& rb = options_.rollback;
  const PlaneStepTimings first_run = result.timings;
  RollBackCounts counts = result.roll_back;
  const int now = iteration_;
  int done = now;  // the state is the end of this iteration
  int restored = 0;
  std::size_t replaying = roll_back_log_.size();  // the log entry whose replay runs
  while (true) {
    if (roll_back_request_) {
      RollBackEvent event = *roll_back_request_;
      roll_back_request_.reset();
      const RltPlaneStorage::Checkpoint* from =
          restored < rb.max_nesting ? storage_.newest_at_or_before(event.target_iteration - 1) : nullptr;
      if (restored >= rb.max_nesting) {
        event.outcome = RollBackOutcome::Nesting;
      } else if (from == nullptr) {
        event.outcome = RollBackOutcome::TooOld;  // spec §5.11.3: refused, and logged
      } else {
        event.outcome = RollBackOutcome::Replayed;
        ++restored;
        storage_.drop_after(from->iteration);
        done = from->iteration;
        static_cast<RltXPointsState&>(*this) = from->state;
      }
      roll_back_log_.push_back(event);
      if (event.outcome == RollBackOutcome::Replayed) {
        ++counts.rollbacks;
        replaying = roll_back_log_.size() - 1;
      } else {
        ++counts.refused;
      }
    }
    if (done >= now) break;
    const PlaneFrame* next = storage_.frame_after(done);
    if (next == nullptr || next->iteration > now)
      throw std::logic_error("RltXPointsS::roll_back: no stored input after iteration " + std::to_string(done));
    result = iterate(*next);
    done = next->iteration;
    counts.hints += result.roll_back.hints;
    ++counts.replayed_iterations;
    ++roll_back_log_[replaying].replayed_iterations;
    storage_.checkpoint_if_due(done, *this, rb.checkpoint_period);
  }
  result.roll_back = counts;
  result.timings = first_run;
  result.timings.roll_back_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void RltXPointsS::start_iteration(int iteration) {
  iteration_ = iteration;
  started_ = true;
  // Only RltPlanes seen within the iteration gap can pass MatchPlane's last test, so Rule 1
  // needs to look at no others (spec §5.15: registration linear in the planes seen).
  const int gap = options_.local_match.max_iteration_gap;
  std::erase_if(recent_, [&](PlaneId p) {
    const bool stale = gap >= 0 && iteration - planes_[p].last_iteration() > gap;
    if (stale) in_recent_[p] = 0;
    return stale;
  });
  taken_.assign(planes_.size(), 0);
  reacquired_now_.clear();
}

void RltXPointsS::add_planes(const PlaneFrame& frame, RelativePlaneStep& result) {
  // The frame's planes stamped with its iteration (MatchPlane's gap test and the arrays use it).
  stamped_.assign(frame.planes.begin(), frame.planes.end());
  for (PlaneObject& p : stamped_) p.iteration = frame.iteration;
  assignment_.assign(stamped_.size(), kNone);
  const RuleSwitches& rules = options_.rules;
  const std::vector<MapPlane>& map = builder_.map();

  // Rule 1: each observation against the previous observation of every recently seen RltPlane
  // (thesis 4.2.1: "the last added untransformed plane in every rltplane"), in the thesis's
  // order (4.5 AddPlane, spec §5.4.2): the RltPlanes in groups first, then the map (Rule 11),
  // and only then the unassigned list. Deviation: the thesis tries the current group and its
  // neighbours before the other groups, as a saving; every RltPlane that can pass the gap test
  // is in `recent_`, and the best score wins among them, so the outcome is the same. The
  // unassigned list must come after the map: a wall re-entering the view as a sliver at the
  // frustum's edge overlaps its mapped plane too little under a small pose error and becomes
  // a new RltPlane; were it matched before the map, every later (larger) observation would
  // follow it there and the wall would be mapped twice (Map D with noise, loop closure).
  // Deviation [C]: while the pose is lost (no pose this iteration or the last) the unassigned
  // list comes first, as the map would be searched with a pose held from long ago.
  auto match_recent = [&](bool grouped) {
    matches_.clear();
    for (int i = 0; i < static_cast<int>(stamped_.size()); ++i) {
      if (assignment_[i] != kNone) continue;
      for (PlaneId p : recent_) {
        const bool mapped = p < static_cast<PlaneId>(map.size()) && map[p].mapped;
        if (grouped != (mapped || !planes_[p].refs().empty())) continue;
        if (!rules.local_registration && mapped) continue;  // Rule 1 off: mapped planes via the pose
        const double score = match_plane(planes_[p].latest(), stamped_[i], options_.local_match, rules.normal_direction);
        if (score >= 0) matches_.push_back({i, p, score});
      }
    }
    register_matches(result.local_matches);
  };
  match_recent(true);

  // Rule 11: what no grouped RltPlane took is placed with a pose and matched to the map.
  bool unassigned_matched = false;
  if (rules.global_matching && last_valid_pose_.valid && std::ranges::count(assignment_, kNone) > 0) {
    const auto [world_T_robot, fresh] = pose_for_global_matching();
    if (!fresh) {
      match_recent(false);
      unassigned_matched = true;
    }
    matches_.clear();
    for (int i = 0; i < static_cast<int>(stamped_.size()); ++i)
      if (assignment_[i] == kNone)
        builder_.match_plane_to_map(i, stamped_[i], world_T_robot, options_.global_match, rules.normal_direction,
                                    taken_, matches_);
    register_matches(result.global_matches, &reacquired_now_);
  }
  if (!unassigned_matched) match_recent(false);

  // Anything left is a plane not seen before: a new RltPlane in the unassigned list.
  for (int i = 0; i < static_cast<int>(stamped_.size()); ++i)
    if (assignment_[i] == kNone) {
      assignment_[i] = create_plane(stamped_[i], i);
      ++result.new_planes;
    }
}

std::pair<PlanarPose, bool> RltXPointsS::pose_for_global_matching() {
  // The thesis places them with the previous iteration's pose (4.2.2). Deviation [C]: this
  // iteration's, from what Rule 1 registered, when that gives one — still computed from this
  // iteration's observations against the map, never carried forward. While turning the previous
  // pose lags by a whole step: 1.5° at 28 units moves a wall by 0.7, past the matching bounds,
  // and the re-seen wall would become a duplicate.
  const bool recent = last_valid_iteration_ >= iteration_ - 1;
  if (motion_model_active_) {
    RltXMMPoint& mm = motion_models_.back();
    mm.compute(planes_, options_.motion_model);
    if (const std::optional<PlanarPose> tracked = mm.world_T_robot(iteration_)) return {*tracked, true};
    return {last_valid_pose_.world_T_robot, recent};
  }
  registered_.clear();
  for (std::size_t i = 0; i < stamped_.size(); ++i)
    if (assignment_[i] != kNone) registered_.push_back({&stamped_[i], assignment_[i]});
  const RltPoset now = builder_.get_poset(registered_, planes_, options_);
  if (now.valid) return {now.world_T_robot, true};
  return {last_valid_pose_.world_T_robot, recent};
}

void RltXPointsS::register_matches(int& counter, std::vector<PlaneId>* registered) {
  // Best score first across all pairs (spec §5.4.1: at most one observation per RltPlane per
  // iteration); ties in input order, then creation order, so runs are deterministic.
  std::ranges::sort(matches_, [](const PlaneMatch& x, const PlaneMatch& y) {
    if (x.score != y.score) return x.score > y.score;
    return std::pair(x.observation, x.plane) < std::pair(y.observation, y.plane);
  });
  for (const PlaneMatch& m : matches_) {
    if (assignment_[m.observation] != kNone || taken_[m.plane]) continue;
    assignment_[m.observation] = m.plane;
    add_to_plane(m.plane, stamped_[m.observation]);
    ++counter;
    if (registered != nullptr) registered->push_back(m.plane);
  }
}

void RltXPointsS::add_to_plane(PlaneId plane, const PlaneObject& observation) {
  // AddtoTPlane: store it, and every group holding the plane has new data to compute.
  planes_[plane].add(observation);
  taken_[plane] = 1;
  for (const RltXPointRef& ref : planes_[plane].refs()) xpoints_[ref.xpoint].mark_changed();
  if (!in_recent_[plane]) {
    in_recent_[plane] = 1;
    recent_.push_back(plane);
  }
}

PlaneId RltXPointsS::create_plane(const PlaneObject& observation, int input_index) {
  const PlaneId id = static_cast<PlaneId>(planes_.size());
  planes_.emplace_back(id, observation, options_.plane_capacity);
  plane_inputs_.push_back(input_index);
  unassigned_.push_back(id);
  recent_.push_back(id);
  in_recent_.push_back(1);
  taken_.push_back(1);
  return id;
}

void RltXPointsS::manage_xpoints(RelativePlaneStep& result) {
  // Rule 29 (spec §5.10.4): leaving a motion model where a group already holds every plane in
  // view goes back to that group instead of starting a new one.
  if (motion_model_active_ && options_.rules.return_to_visited_group) {
    const bool pseudo_merge = options_.key_points && options_.rules.pseudo_merge;
    bool returned = switch_to_group_holding_all();
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
      const std::vector<DuplicateGroup> duplicates = find_duplicate_groups(world_T_robot);
      if (!returned) returned = switch_to_group_holding_all(duplicates);
      if (returned) result.oneway_links += mend_merge_after_loop_closing(duplicates);
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
    end_motion_model_on_the_map();
  upkeep_unassigned();
  // Step D: the current group by charting (Rule 22); off, the group last started stays current,
  // as before Rule 22 in the thesis (4.3.5).
  if (options_.key_points && options_.rules.current_group_chart) chart_current_group();
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

void RltXPointsS::end_motion_model_on_the_map() {
  // Spec §5.10.4 [T/P]: the motion model ends once a second plane comes into view. Rule 29 ends
  // it when one group holds every plane in view, a new group when the second plane is new. When
  // the second plane is on the map already, in no group with the motion model's plane and at
  // Rule 21's membership cap, neither comes (Map E's fourth corner from the third loop: the
  // motion model tracked the start wall on, the pose drifting 0.05 an iteration). [C] Then the
  // chart's group — the one holding most planes in view — becomes current; the pose is GetPoset's.
  // Part of Rule 29 (a return to where the robot has been): off with it.
  const std::vector<MapPlane>& map = builder_.map();
  const PlaneId tracked = motion_models_.back().plane();
  const bool second_on_map = std::ranges::any_of(assignment_, [&](PlaneId p) {
    return p != tracked && p < static_cast<PlaneId>(map.size()) && map[p].mapped;
  });
  if (!second_on_map) return;
  fill_chart(false);
  const auto best = std::ranges::max_element(chart_);  // the first of the most: the lowest id
  if (*best > 0) set_current(static_cast<XPointId>(best - chart_.begin()));
}

void RltXPointsS::fill_chart(bool oneway_links) {
  // RltXPointChart's counts: per group (motion models aside), the planes in view it holds.
  chart_.assign(xpoints_.size(), 0);
  for (PlaneId p : assignment_) {
    for (const RltXPointRef& ref : planes_[p].refs())
      if (!xpoints_[ref.xpoint].motion_model()) ++chart_[ref.xpoint];
    if (!oneway_links) continue;
    for (XPointId y : planes_[p].oneway_xpoints())  // Rule 37: as if merged with its duplicates
      if (planes_[p].ref(y) == nullptr) ++chart_[y];    // (unless it has since joined that group)
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
      set_current(create_xpoint(std::move(chain), x, std::move(linking), plane));
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
    return planes_[p].ref(x.id()) != nullptr || std::ranges::any_of(through, [&](const DuplicateGroup& d) {
             return d.plane == p && d.xpoint == x.id();
           });
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

void RltXPointsS::compute_xpoints(RelativePlaneStep& result) {
  const bool reorder = options_.key_points && (options_.rules.reorder_planes || options_.rules.reorder_broken_chains);
  for (RltXPoint& x : xpoints_)
    if (x.needs_compute() && !x.motion_model()) {
      if (reorder) x.reorder_if_due(planes_, options_, iteration_);  // Rule 30 (spec §5.7.1)
      x.compute(planes_, options_);
      if (options_.rules.interval_check) check_interval_sizes(x, result);  // Rules 31, 32 (walkthrough 4.5)
      ++result.groups_computed;
    }
  // A motion model re-runs its track over its plane's observations (spec §5.10.3).
  for (RltXMMPoint& mm : motion_models_) {
    RltXPoint& x = xpoints_[mm.xpoint()];
    if (!x.needs_compute()) continue;
    if (!mm.ended()) mm.compute(planes_, options_.motion_model);  // an ended track is frozen
    x.compute(planes_, options_);  // only clears the flag
    ++result.groups_computed;
  }
}

void RltXPointsS::get_poset() {
  registered_.clear();
  for (std::size_t i = 0; i < stamped_.size(); ++i) registered_.push_back({&stamped_[i], assignment_[i]});
  pose_ = builder_.get_poset(registered_, planes_, options_);
  if (!pose_.valid && !motion_model_active_) check_for_motion_model();
  // While a motion model is active its track is the pose (spec §5.10.3), also for Rule 11.
  if (motion_model_active_) {
    const std::optional<PlanarPose> tracked = motion_models_.back().world_T_robot(iteration_);
    pose_ = {tracked.value_or(PlanarPose{}), tracked.has_value(), tracked ? 1 : 0};
  }
  if (pose_.valid) {
    last_valid_pose_ = pose_;
    last_valid_iteration_ = iteration_;
    no_pose_count_ = 0;
  }
}

void RltXPointsS::check_for_motion_model() {
  // Rule 26 (CheckForMotionModel): a few iterations without a pose within a short window.
  if (no_pose_count_ == 0 || iteration_ - no_pose_start_ > options_.motion_model.start_window) {
    no_pose_count_ = 0;
    no_pose_start_ = iteration_;
  }
  ++no_pose_count_;
  if (!options_.key_points || !options_.rules.motion_model || !last_valid_pose_.valid) return;
  if (no_pose_count_ < options_.motion_model.start_after) return;
  // [R, spec §5.10.2] exactly one plane in view, and it is on the map; blind or lost otherwise.
  if (assignment_.size() != 1 || !builder_.map()[assignment_.front()].mapped) return;
  create_motion_model(assignment_.front());
}

void RltXPointsS::create_motion_model(PlaneId plane) {
  // CreateMotionModelXPoint (Rule 27): a new group holding the one plane, linked from the
  // current group through it and fixed at the last valid pose. Entering a motion model always
  // makes a new one [T].
  const XPointId id = static_cast<XPointId>(xpoints_.size());
  planes_[plane].join(id, iteration_);
  founders_.push_back(kNone);
  RltXPoint& x = xpoints_.emplace_back(id, iteration_, std::vector<PlaneId>{plane});
  x.set_anchor(last_valid_pose_.world_T_robot);
  links_.push_back({current_, id, {plane}, false, iteration_});
  if (current_ != kNone) {
    xpoints_[current_].add_adjacent(id);
    xpoints_[id].add_adjacent(current_);
  }
  motion_models_.emplace_back(id, plane, last_valid_pose_.world_T_robot, last_valid_iteration_,
                              builder_.map()[plane].plane);
  motion_model_active_ = true;
  current_ = id;
  // Computed and placed at once, so this iteration already has its pose.
  motion_models_.back().compute(planes_, options_.motion_model);
  xpoints_[id].compute(planes_, options_);
  builder_.build_map(links_, xpoints_, planes_, world_T_start_, options_);
}

}  // namespace relslam::plane
