#include "relslam/point/rlt_point_merging.hpp"

#include <algorithm>

namespace relslam::point {

int RltPointMerging::merge_due(RltMap& map, int k, double bound) {
  int merges = 0;
  while (!checks_.empty() && checks_.front().first <= k) {
    const PointId id = checks_.front().second;
    checks_.pop_front();
    const PointId older = merge_partner(map, id, bound);
    if (older == kNone) continue;
    merge_points(map, id, older, k);
    ++merges;
  }
  return merges;
}

PointId merge_partner(RltMap& map, PointId id, double bound) {
  const RltPoint& p = map.points[id];
  if (!p.on_map()) return kNone;
  PointId best = kNone;
  double best_distance = bound;
  for (PointId q : map.global_index->query(p.global)) {
    const RltPoint& older = map.points[q];
    if (q == id || !older.on_map() || older.creation_iteration >= p.creation_iteration) continue;
    if (older.last_iteration() >= p.interval.first()) continue;  // seen together: two landmarks
    const double d = (older.global - p.global).norm();
    if (d <= best_distance) best_distance = d, best = q;
  }
  return best;
}

void merge_points(RltMap& map, PointId newer_id, PointId older_id, int k) {
  RltPoint& newer = map.points[newer_id];
  RltPoint& older = map.points[older_id];
  const int from = newer.interval.first();
  // The older point takes every observation (all later than its own: they are disjoint).
  for (int i = newer.observations.lower_bound(from); i < newer.observations.size(); ++i) {
    older.observations.push(newer.observations[i]);
    older.interval.add(newer.observations[i].iteration);
  }
  map.charting.replace(newer_id, older_id);

  // The older point's groups can use the copied iterations now.
  for (const RltGroupRef& ref : older.groups)
    if (map.groups[ref.group].alive()) map.compute(map.groups[ref.group], from, k);
  // The newer point's groups get the older point instead, as an anchor: its sums stay valid
  // (the observations are the same) and its map position stays the older point's.
  for (const RltGroupRef& ref : std::vector<RltGroupRef>(newer.groups)) {
    RltGroup& g = map.groups[ref.group];
    if (!g.alive()) continue;
    const auto& m = g.members();
    if (std::find(m.begin(), m.end(), older_id) != m.end()) {
      map.retire(g);  // both in one group: it could never have been computed consistently
      continue;
    }
    g.replace_member(ref.member, older_id);
    map.points[older_id].groups.push_back(ref);
  }
  newer.groups.clear();
  map.temporary_list.remove(newer_id);
  map.final_list.remove(newer_id);
  map.global_index->remove(newer_id);
  newer.merged = true;
  newer.merged_into = older_id;
  map.mark_changed(newer_id);
  ++map.stats.merged_points;
}

}  // namespace relslam::point
