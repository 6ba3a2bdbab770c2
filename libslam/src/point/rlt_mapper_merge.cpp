// RltMapper: RltPoint merging (thesis 6.5.2, spec 5.9).
#include "relslam/point/rlt_mapper.hpp"

#include <algorithm>

namespace relslam::point {
namespace {

constexpr double kBasisEpsilon = 1e-6;  // as in group computation [C]

}  // namespace

void RltMapper::merge_due(int k, StepResult& result) {
  while (!merge_checks_.empty() && merge_checks_.front().first <= k) {
    const PointId id = merge_checks_.front().second;
    merge_checks_.pop_front();
    const RltPoint& p = points_[id];
    if (!p.on_map()) continue;
    // The closest older, mapped point never seen while p was: the same landmark, found again.
    PointId best = kNone;
    double best_distance = options_.merge_bound;
    for (PointId q : global_index_->query(p.global)) {
      const RltPoint& older = points_[q];
      if (q == id || !older.on_map() || older.creation_iteration >= p.creation_iteration) continue;
      if (older.last_iteration() >= p.interval.first()) continue;  // seen together: two landmarks
      const double d = (older.global - p.global).norm();
      if (d <= best_distance) best_distance = d, best = q;
    }
    if (best == kNone) continue;
    merge(id, best, k);
    ++result.merges;
  }
}

void RltMapper::merge(PointId newer_id, PointId older_id, int k) {
  RltPoint& newer = points_[newer_id];
  RltPoint& older = points_[older_id];
  const int from = newer.interval.first();
  // The older point takes every observation (all later than its own: they are disjoint).
  for (int i = newer.observations.lower_bound(from); i < newer.observations.size(); ++i) {
    older.observations.push(newer.observations[i]);
    older.interval.add(newer.observations[i].iteration);
  }
  charting_.replace(newer_id, older_id);

  // The older point's groups can use the copied iterations now.
  for (const RltGroupRef& ref : older.groups)
    if (groups_[ref.group].alive() && groups_[ref.group].accumulate(points_, from, k, kBasisEpsilon)) anchor(groups_[ref.group]);
  // The newer point's groups get the older point instead, as an anchor: its sums stay valid
  // (the observations are the same) and its map position stays the older point's.
  for (const RltGroupRef& ref : std::vector<RltGroupRef>(newer.groups)) {
    RltGroup& g = groups_[ref.group];
    if (!g.alive()) continue;
    const auto& m = g.members();
    if (std::find(m.begin(), m.end(), older_id) != m.end()) {
      retire(g);  // both in one group: it could never have been computed consistently
      continue;
    }
    g.replace_member(ref.member, older_id);
    points_[older_id].groups.push_back(ref);
  }
  newer.groups.clear();
  temporary_list_.remove(newer_id);
  final_list_.remove(newer_id);
  global_index_->remove(newer_id);
  newer.merged = true;
  newer.merged_into = older_id;
  mark_changed(newer_id);
  ++stats_.merged_points;
}

}  // namespace relslam::point
