// RltMapper: group computation, creation, dynamic points and clean-up (thesis 6.3-6.5.5).
#include "relslam/point/rlt_mapper.hpp"

#include <algorithm>

namespace relslam::point {
namespace {

constexpr double kBasisEpsilon = 1e-6;  // relative degeneracy tolerance of one iteration's basis [C]

}  // namespace

void RltMapper::compute_groups(int k) {
  std::sort(queued_groups_.begin(), queued_groups_.end());
  for (GroupId g : queued_groups_) {
    RltGroup& group = groups_[g];
    if (group.alive() && group.accumulate(points_, k, k, kBasisEpsilon)) anchor(group);
  }
  queued_groups_.clear();
}

void RltMapper::anchor(RltGroup& group) {
  const auto world_T_group = group.registration(points_, first_iteration_);
  if (!world_T_group) return;
  for (std::size_t i = 0; i < group.members().size(); ++i) {
    const PointId id = group.members()[i];
    const RltPoint& p = points_[id];
    // Anchors are registration sources and never rewritten by this group (spec 5.5).
    if (group.anchor(static_cast<int>(i)) || p.owner != group.id() || p.dynamic || p.merged) continue;
    set_global(id, *world_T_group * group.relative(static_cast<int>(i)));
  }
}

void RltMapper::create_groups(int k, StepResult& result) {
  for (GroupLevel level : {GroupLevel::Temporary, GroupLevel::Final}) {
    if (!level_options(level).enabled) continue;
    RltUngroupedList& waiting = list(level);
    const int look_ahead = level_options(level).look_ahead;
    // Process every entry that is ready; the list is in start order (spec 5.6, A40).
    while (!waiting.empty() && k >= waiting.front().start + look_ahead) {
      const RltUngroupedList::Entry entry = waiting.front();
      waiting.pop_front();
      if (try_create(level, entry, k, result)) ++result.groups_created;
    }
  }
  if (options_.level3.enabled) create_level3_groups(k, result);
  // Every point of the first iteration has had its chance to root the map and none could: the
  // map frame (the first observations, thesis 6.3.3) can never be fixed.
  const RltUngroupedList& lowest = list(options_.temporary_group.enabled ? GroupLevel::Temporary : GroupLevel::Final);
  const bool first_iteration_tried = lowest.empty() || lowest.front().start > first_iteration_;
  if (!any_mapped_ && failure_.empty() && first_iteration_tried && !options_.provisional_root)
    failure_ = "no group could be anchored to the first iteration's observations (the map frame): fewer than 3 points "
               "were seen there often enough";
}

bool RltMapper::try_create(GroupLevel level, const RltUngroupedList::Entry& entry, int k, StepResult& result) {
  const RltPoint& c = points_[entry.id];
  if (c.dynamic || c.merged) return false;
  LevelContext context;
  context.level = level;
  context.options = &level_options(level);
  context.ungrouped = &list(level);
  context.level_mapped = level == GroupLevel::Temporary || !options_.temporary_group.enabled ? any_mapped_
                                                                                            : stats_.final_created > 0;
  context.lowest = level == GroupLevel::Temporary || !options_.temporary_group.enabled;
  context.first_iteration = first_iteration_;
  PlanOutcome outcome = planner_.plan(entry.id, entry.start, k, context, points_, charting_, options_);
  result.timings.binning_ms += outcome.binning_ms;
  result.binning_comparisons += outcome.comparisons;
  for (PointId id : outcome.dynamic) mark_dynamic(id, result);
  if (!outcome.plan) return false;
  const GroupPlan& plan = *outcome.plan;

  build_group(level, entry.start, k, plan);
  return true;
}

void RltMapper::create_level3_groups(int k, StepResult& result) {
  // A point is ready once out of view; it gets this one chance (spec 5.12).
  std::size_t kept = 0;
  for (PointId id : level3_waiting_) {
    const RltPoint& p = points_[id];
    if (p.dynamic || p.merged || p.level3_grouped) continue;
    if (p.last_iteration() >= k - options_.level3.gap) {
      level3_waiting_[kept++] = id;
      continue;
    }
    PlanOutcome outcome = planner_.plan_level3(id, k, points_, charting_, options_);
    result.timings.binning_ms += outcome.binning_ms;
    result.binning_comparisons += outcome.comparisons;
    for (PointId d : outcome.dynamic) mark_dynamic(d, result);
    if (!outcome.plan) continue;
    build_group(GroupLevel::Level3, p.interval.first(), k, *outcome.plan);
    ++result.groups_created;
  }
  level3_waiting_.resize(kept);
}

void RltMapper::build_group(GroupLevel level, int c0, int k, const GroupPlan& plan) {
  const auto id = static_cast<GroupId>(groups_.size());
  groups_.emplace_back(id, level, c0, k, plan.members, plan.anchor, plan.basis, plan.registration);
  ++stats_.created;
  ++stats_.alive;
  stats_.alive_members += static_cast<long long>(plan.members.size());
  if (level == GroupLevel::Final) ++stats_.final_created;
  if (level == GroupLevel::Level3) ++stats_.level3_created;
  if (level == GroupLevel::Temporary) {
    ++stats_.temporary_alive;
    temporary_to_review_.push_back(id);
  }

  for (std::size_t i = 0; i < plan.members.size(); ++i) {
    RltPoint& p = points_[plan.members[i]];
    p.groups.push_back({id, static_cast<int>(i)});
    if (plan.anchor[i]) continue;
    // Ownership (spec 5.6): level 3 and final groups always take their new members; a
    // temporary group only those no final or level-3 group owns. The higher levels thus map
    // everything they hold (6.5.5).
    switch (level) {
      case GroupLevel::Level3:
        p.level3_grouped = true;
        p.owner = id;
        break;
      case GroupLevel::Final:
        list(level).remove(p.id);
        p.final_grouped = true;
        if (!p.level3_grouped) p.owner = id;
        break;
      case GroupLevel::Temporary:
        list(level).remove(p.id);
        p.temporary_grouped = true;
        if (!p.final_grouped && !p.level3_grouped) p.owner = id;
        break;
    }
  }
  RltGroup& group = groups_.back();
  if (group.accumulate(points_, c0, k, kBasisEpsilon)) anchor(group);
}

void RltMapper::mark_dynamic(PointId id, StepResult& result) {
  RltPoint& p = points_[id];
  if (p.dynamic) return;
  // Off the map and out of every list, anchor set and global match (spec A22); still matched
  // locally so it keeps one RltPoint.
  p.dynamic = true;
  temporary_list_.remove(id);
  final_list_.remove(id);
  global_index_->remove(id);
  mark_changed(id);
  ++result.dynamic_flagged;
  ++stats_.dynamic_points;
  // A group with a moving basis point has no consistent frame: its averages are meaningless.
  for (const RltGroupRef& ref : std::vector<RltGroupRef>(p.groups)) {
    RltGroup& g = groups_[ref.group];
    const auto& b = g.basis();
    if (g.alive() && std::find(b.begin(), b.end(), ref.member) != b.end()) retire(g);
  }
}

void RltMapper::retire(RltGroup& group) {
  group.retire();
  --stats_.alive;
  stats_.alive_members -= static_cast<long long>(group.members().size());
  if (group.level() == GroupLevel::Temporary) --stats_.temporary_alive;
  for (PointId id : group.members()) {
    auto& refs = points_[id].groups;
    refs.erase(std::remove_if(refs.begin(), refs.end(), [&](const RltGroupRef& r) { return r.group == group.id(); }),
               refs.end());
  }
}

void RltMapper::retire_redundant_temporary_groups(int k) {
  // A temporary group's new members are offered to final groups within the final look-ahead;
  // after that, a group that owns none of its members maps nothing and only costs time.
  const int settled = k - options_.final_group.look_ahead - options_.temporary_group.look_ahead;
  while (!temporary_to_review_.empty() && groups_[temporary_to_review_.front()].built_at() <= settled) {
    RltGroup& group = groups_[temporary_to_review_.front()];
    temporary_to_review_.pop_front();
    if (!group.alive()) continue;
    const bool owns_any = std::any_of(group.members().begin(), group.members().end(), [&](PointId id) {
      return points_[id].owner == group.id();
    });
    if (!owns_any) retire(group);  // otherwise it still maps a point no final group took: kept
  }
}

}  // namespace relslam::point
