#include "relslam/point/group_planning.hpp"

#include <algorithm>
#include <cstdint>

namespace relslam::point {
namespace {

// SplitMix64 finaliser: a fixed pseudo-random order of ids.
std::uint64_t tie_break(PointId id) {
  std::uint64_t z = static_cast<std::uint64_t>(id) + 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

}  // namespace

bool GroupPlanner::previously_mapped(const RltPoint& p, const LevelContext& level, int c0) const {
  if (!p.on_map()) return false;
  if (level.level == GroupLevel::Temporary) return true;
  // Final groups build only on final groups (thesis 6.5.5). Until the first final group exists,
  // a candidate other than the first iteration's may fall back on temporary anchors (spec 5.6).
  return p.final_grouped || (!level.level_mapped && c0 != level.first_iteration);
}

std::vector<Eigen::Vector3d> GroupPlanner::basis_positions(const std::vector<PointId>& members,
                                                           const std::vector<RltPoint>& points, int c0, int k) const {
  // The latest iteration with every member observed (spec 5.8); else each one's latest.
  std::vector<Eigen::Vector3d> positions(members.size());
  for (int t = k; t >= c0; --t) {
    bool all = true;
    for (std::size_t i = 0; i < members.size() && all; ++i) {
      const Point* o = points[members[i]].observations.at(t);
      if (o) positions[i] = o->p;
      all = o != nullptr;
    }
    if (all) return positions;
  }
  for (std::size_t i = 0; i < members.size(); ++i) positions[i] = points[members[i]].observations.latest().p;
  return positions;
}

bool GroupPlanner::keep_static(GroupPlan& plan, PointId c, int c0, int k, const GroupLevelOptions& level,
                               const std::vector<RltPoint>& points, const BinningOptions& binning,
                               PlanOutcome& outcome) const {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<PointId>& m = plan.members;
  const BinningResult bins = rlt_binning(
      static_cast<int>(m.size()),
      [&](int i, int j) {
        return pair_distance_std(points[m[i]].observations, points[m[j]].observations, c0, k, binning.min_pair_samples);
      },
      binning);
  outcome.comparisons = bins.comparisons;
  GroupPlan kept;
  kept.root = plan.root;
  int anchors = 0, fresh = 0;
  bool c_static = false;
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (!bins.is_static[i]) {
      outcome.dynamic.push_back(m[i]);
      continue;
    }
    kept.members.push_back(m[i]);
    kept.anchor.push_back(plan.anchor[i]);
    (plan.anchor[i] ? anchors : fresh) += 1;
    c_static = c_static || m[i] == c;
  }
  outcome.binning_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  plan = std::move(kept);
  // Enough static points left (spec A21): c itself, three anchors to register, NextGroupMin new.
  return c_static && (plan.root || anchors >= 3) && fresh >= level.next_min;
}

PlanOutcome GroupPlanner::plan(PointId c, int c0, int k, const LevelContext& level, const std::vector<RltPoint>& points,
                               RltPointCharting& charting, const PointSlamOptions& options) {
  PlanOutcome outcome;
  const GroupLevelOptions& o = *level.options;
  const int ahead = c0 + o.look_ahead;
  const int need = o.look_ahead - o.accuracy_reduction;
  auto count_new = [&](const RltPoint& p) { return p.interval.count(c0, ahead); };
  // Most observed first. Many candidates tie (seen in the whole window); ties go by a hash
  // of the id, which spreads the choice over the frustum like the thesis's effectively random
  // enumeration order, while staying independent of input order. Ordering ties by id instead
  // picks the oldest points, all near the robot: the new points, far ahead, are then
  // extrapolated from a tight cluster and the map's roll and pitch errors grow group by group.
  auto rank = [this](std::vector<PointId>& out) {
    std::sort(ranked_.begin(), ranked_.end(), [](const auto& a, const auto& b) {
      if (a.first != b.first) return a.first > b.first;
      const auto ha = tie_break(a.second), hb = tie_break(b.second);
      return ha != hb ? ha < hb : a.second < b.second;
    });
    for (const auto& [count, id] : ranked_) out.push_back(id);
  };

  GroupPlan plan;
  plan.root = !level.level_mapped && c0 == level.first_iteration;
  auto no_group = [&outcome] { return std::move(outcome); };

  // Previously mapped candidates seen around c0, most observed first (thesis 6.4.3 step 3).
  scratch_.clear();
  charting.enumerate_unique(c0 - o.look_back, ahead, scratch_);
  ranked_.clear();
  for (PointId id : scratch_) {
    const RltPoint& p = points[id];
    if (previously_mapped(p, level, c0) && count_new(p) >= need) ranked_.push_back({p.interval.count(c0 - o.look_back, ahead), id});
  }
  rank(plan.members);
  if (static_cast<int>(plan.members.size()) > o.prev_max) plan.members.resize(o.prev_max);
  const std::size_t anchors = plan.members.size();
  if (!plan.root && static_cast<int>(anchors) < o.prev_min) return no_group();

  // Still-ungrouped points seen in [c0, c0 + A], c itself included (step 4).
  scratch_.clear();
  charting.enumerate_unique(c0, ahead, scratch_);
  ranked_.clear();
  bool has_c = false;
  for (PointId id : scratch_) {
    const RltPoint& p = points[id];
    if ((id != c && !level.ungrouped->contains(id)) || p.dynamic || p.merged) continue;
    if (std::find(plan.members.begin(), plan.members.begin() + anchors, id) != plan.members.begin() + anchors) continue;
    const int n = count_new(p);
    if (n < need) continue;
    has_c = has_c || id == c;
    ranked_.push_back({n, id});
  }
  if (!has_c || static_cast<int>(ranked_.size()) < o.next_min) return no_group();
  rank(plan.members);
  plan.anchor.assign(plan.members.size(), false);
  std::fill(plan.anchor.begin(), plan.anchor.begin() + static_cast<std::ptrdiff_t>(anchors), true);
  if (o.binning && !keep_static(plan, c, c0, k, o, points, options.binning, outcome)) return no_group();

  if (plan.root) {  // the map frame comes from the first observations: three are needed
    const auto seen_first = std::count_if(plan.members.begin(), plan.members.end(), [&](PointId id) {
      return points[id].first_observation.iteration == level.first_iteration;
    });
    if (seen_first < 3) return no_group();
  }

  const auto basis = select_basis(basis_positions(plan.members, points, c0, k), options.basis, options.min_basis_ratio);
  if (!basis) return no_group();
  plan.basis = *basis;
  outcome.plan = std::move(plan);
  return outcome;
}

}  // namespace relslam::point
