#include "relslam/point/group_creation.hpp"

#include <algorithm>

namespace relslam::point {
const GroupLevelOptions& level_options(const PointSlamOptions& options, GroupLevel level) {
  return level == GroupLevel::Temporary ? options.temporary_group : options.final_group;
}

void wait_for_group(RltMap& map, PointId id, GroupLevel level, int start, const PointSlamOptions& options,
                    bool restart) {
  const RltPoint& p = map.points[id];
  // A final member is mapped by final groups only, and needs no temporary group (6.5.5).
  const bool grouped = level == GroupLevel::Temporary ? p.temporary_grouped || p.final_grouped : p.final_grouped;
  if (!level_options(options, level).enabled || grouped) return;
  RltUngroupedList& list = map.list(level);
  if (restart) list.remove(id);
  list.push(id, start);
}

void GroupCreation::add_point(PointId id, const PointSlamOptions& options) {
  if (options.level3.enabled) level3_waiting_.push_back(id);
}

CreationReport GroupCreation::create_groups(RltMap& map, int k, const PointSlamOptions& options) {
  CreationReport report;
  for (GroupLevel level : {GroupLevel::Temporary, GroupLevel::Final}) {
    if (!level_options(options, level).enabled) continue;
    RltUngroupedList& waiting = map.list(level);
    const int look_ahead = level_options(options, level).look_ahead;
    // Process every entry that is ready; the list is in start order (thesis 6.4).
    while (!waiting.empty() && k >= waiting.front().start + look_ahead) {
      const RltUngroupedList::Entry entry = waiting.front();
      waiting.pop_front();
      if (try_create(map, level, entry, k, options, report)) continue;
      // The thesis gives a point one chance per visible run. Deviation (adaptive preset, issue
      // 16): one still in view waits again from now, so a point whose first window lacked
      // anchors (a sparse scene) is grouped once enough mapped points are around it.
      const RltPoint& c = map.points[entry.id];
      if (options.preset == Preset::Adaptive && !c.dynamic && !c.merged && c.last_iteration() >= k - options.match_look_back)
        wait_for_group(map, entry.id, level, k, options);
    }
  }
  if (options.level3.enabled) create_level3_groups(map, k, options, report);
  return report;
}

bool GroupCreation::try_create(RltMap& map, GroupLevel level, const RltUngroupedList::Entry& entry, int k,
                               const PointSlamOptions& options, CreationReport& report) {
  const RltPoint& c = map.points[entry.id];
  if (c.dynamic || c.merged) return false;
  // The lowest level switched on builds on any map position; the final level above temporary
  // groups builds on final groups only (thesis 6.5.5).
  const bool lowest = level == GroupLevel::Temporary || !options.temporary_group.enabled;
  LevelContext context;
  context.level = level;
  context.options = &level_options(options, level);
  context.ungrouped = &map.list(level);
  context.level_mapped = lowest ? map.any_mapped : map.stats.final_created > 0;
  context.lowest = lowest;
  context.first_iteration = map.first_iteration;
  const PlanOutcome outcome = planner_.plan(entry.id, entry.start, k, context, map.points, map.charting, options);
  return apply(map, level, entry.start, k, outcome, report);
}

void GroupCreation::create_level3_groups(RltMap& map, int k, const PointSlamOptions& options, CreationReport& report) {
  // A point is ready once out of view; it gets this one chance (thesis 6.5.5).
  std::size_t kept = 0;
  for (PointId id : level3_waiting_) {
    const RltPoint& p = map.points[id];
    if (p.dynamic || p.merged || p.level3_grouped) continue;
    if (p.last_iteration() >= k - options.level3.gap) {
      level3_waiting_[kept++] = id;
      continue;
    }
    const PlanOutcome outcome = planner_.plan_level3(id, k, map.points, map.charting, options);
    apply(map, GroupLevel::Level3, p.interval.first(), k, outcome, report);
  }
  level3_waiting_.resize(kept);
}

bool GroupCreation::apply(RltMap& map, GroupLevel level, int c0, int k, const PlanOutcome& outcome,
                          CreationReport& report) {
  report.binning_ms += outcome.binning_ms;
  report.binning_comparisons += outcome.comparisons;
  for (PointId id : outcome.dynamic)
    if (mark_dynamic(map, id)) ++report.dynamic_flagged;
  if (!outcome.plan) return false;
  build_group(map, level, c0, k, *outcome.plan);
  ++report.groups_created;
  return true;
}

void GroupCreation::build_group(RltMap& map, GroupLevel level, int c0, int k, const GroupPlan& plan) {
  const auto id = static_cast<GroupId>(map.groups.size());
  map.groups.emplace_back(id, level, c0, k, plan.members, plan.anchor, plan.basis, plan.registration);
  GroupStats& stats = map.stats;
  ++stats.created;
  ++stats.alive;
  stats.alive_members += static_cast<long long>(plan.members.size());
  if (level == GroupLevel::Final) ++stats.final_created;
  if (level == GroupLevel::Level3) ++stats.level3_created;
  if (level == GroupLevel::Temporary) {
    ++stats.temporary_alive;
    temporary_to_review_.push_back(id);
  }

  for (std::size_t i = 0; i < plan.members.size(); ++i) {
    RltPoint& p = map.points[plan.members[i]];
    p.groups.push_back({id, static_cast<int>(i)});
    if (plan.anchor[i]) continue;
    // Ownership (thesis 6.4): level 3 and final groups always take their new members; a
    // temporary group only those no final or level-3 group owns. The higher levels thus map
    // everything they hold (6.5.5).
    switch (level) {
      case GroupLevel::Level3:
        p.level3_grouped = true;
        p.owner = id;
        break;
      case GroupLevel::Final:
        map.list(level).remove(p.id);
        p.final_grouped = true;
        if (!p.level3_grouped) p.owner = id;
        break;
      case GroupLevel::Temporary:
        map.list(level).remove(p.id);
        p.temporary_grouped = true;
        if (!p.final_grouped && !p.level3_grouped) p.owner = id;
        break;
    }
  }
  map.compute(map.groups.back(), c0, k);
}

void GroupCreation::retire_redundant_temporary_groups(RltMap& map, int k, const PointSlamOptions& options) {
  // A temporary group's new members are offered to final groups within the final look-ahead;
  // after that, a group that owns none of its members maps nothing and only costs time.
  const int settled = k - options.final_group.look_ahead - options.temporary_group.look_ahead;
  while (!temporary_to_review_.empty() && map.groups[temporary_to_review_.front()].built_at() <= settled) {
    RltGroup& group = map.groups[temporary_to_review_.front()];
    temporary_to_review_.pop_front();
    if (!group.alive()) continue;
    const bool owns_any = std::any_of(group.members().begin(), group.members().end(),
                                      [&](PointId id) { return map.points[id].owner == group.id(); });
    if (!owns_any) map.retire(group);  // otherwise it still maps a point no final group took: kept
  }
}

bool mark_dynamic(RltMap& map, PointId id) {
  RltPoint& p = map.points[id];
  if (p.dynamic) return false;
  p.dynamic = true;
  map.temporary_list.remove(id);
  map.final_list.remove(id);
  map.global_index->remove(id);
  map.mark_changed(id);
  ++map.stats.dynamic_points;
  for (const RltGroupRef& ref : std::vector<RltGroupRef>(p.groups)) {
    RltGroup& g = map.groups[ref.group];
    const auto& b = g.basis();
    if (g.alive() && std::find(b.begin(), b.end(), ref.member) != b.end()) map.retire(g);
  }
  return true;
}

}  // namespace relslam::point
