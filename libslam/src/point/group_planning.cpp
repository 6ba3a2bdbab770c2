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

// The span of the first visible run starting at `from`: runs separated by at most `gap`
// missing iterations count as one.
int span_of(int s, int e) { return e - s + 1; }

int visible_run_end(const RltInterval& interval, int gap) {
  const auto& runs = interval.runs();
  int end = runs.front().end;
  for (std::size_t i = 1; i < runs.size() && runs[i].start - end - 1 <= gap; ++i) end = runs[i].end;
  return end;
}

// Points seen per iteration over [a, b], on average (the adaptive preset's PrevGroupMin).
double in_view(const RltPointCharting& charting, int a, int b) {
  std::size_t seen = 0;
  for (int t = a; t <= b; ++t) seen += charting.at(t).size();
  return static_cast<double>(seen) / (b - a + 1);
}

}  // namespace

// Most observed first. Many candidates tie (seen in the whole window); ties go by a hash of the
// id, which spreads the choice over the frustum like the thesis's effectively random
// enumeration order, while staying independent of input order. Ordering ties by id instead
// picks the oldest points, all near the robot: the new points, far ahead, are then
// extrapolated from a tight cluster and the map's roll and pitch errors grow group by group.
void GroupPlanner::rank(std::vector<PointId>& out, std::size_t limit) {
  // A total order (ids are distinct), so only the first `limit` need sorting.
  const auto order = [](const Ranked& a, const Ranked& b) {
    if (a.count != b.count) return a.count > b.count;
    return a.tie != b.tie ? a.tie < b.tie : a.id < b.id;
  };
  const auto end = ranked_.begin() + static_cast<std::ptrdiff_t>(std::min(limit, ranked_.size()));
  std::partial_sort(ranked_.begin(), end, ranked_.end(), order);
  for (auto r = ranked_.begin(); r != end; ++r) out.push_back(r->id);
}

void GroupPlanner::candidate(int count, PointId id) {
  ranked_.push_back({count, tie_break(id), id});  // the hash once, not per comparison
}

bool GroupPlanner::previously_mapped(const RltPoint& p, const LevelContext& level, int c0) const {
  if (!p.on_map()) return false;
  if (level.level == GroupLevel::Temporary) return true;
  // Final groups build only on final groups (thesis 6.5.5). Until the first final group exists,
  // a candidate other than the first iteration's may fall back on temporary anchors (thesis 6.4).
  return p.final_grouped || (!level.level_mapped && c0 != level.first_iteration);
}

std::vector<Eigen::Vector3d> GroupPlanner::basis_positions(const std::vector<PointId>& members,
                                                           const std::vector<RltPoint>& points, int c0, int k) const {
  // The latest iteration with every member observed (thesis 6.5.4); else each one's latest.
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
                               int fewest_anchors, const std::vector<RltPoint>& points,
                               const BinningOptions& binning, PlanOutcome& outcome) const {
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
  kept.registration = plan.registration;
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
  // Enough static points left: c itself, three anchors to register (two with two-point
  // registration), NextGroupMin new.
  return c_static && (plan.root() || anchors >= fewest_anchors) && fresh >= level.next_min;
}

PlanOutcome GroupPlanner::plan(PointId c, int c0, int k, const LevelContext& level, const std::vector<RltPoint>& points,
                               RltPointCharting& charting, const PointSlamOptions& options) {
  PlanOutcome outcome;
  const GroupLevelOptions& o = *level.options;
  const int ahead = c0 + o.look_ahead;
  const int need = o.look_ahead - o.accuracy_reduction;
  auto count_new = [&](const RltPoint& p) { return p.interval.count(c0, ahead); };
  GroupPlan plan;
  // The root group fixes the map frame from the first iteration's observations (thesis 6.3.3).
  if (!level.level_mapped && c0 == level.first_iteration) plan.registration = Registration::FirstObservations;
  auto no_group = [&outcome] { return std::move(outcome); };

  // Previously mapped candidates seen around c0, most observed first (thesis 6.4.3 step 3).
  scratch_.clear();
  charting.enumerate_unique(c0 - o.look_back, ahead, scratch_);
  ranked_.clear();
  for (PointId id : scratch_) {
    const RltPoint& p = points[id];
    if (previously_mapped(p, level, c0) && count_new(p) >= need)
      candidate(p.interval.count(c0 - o.look_back, ahead), id);
  }
  rank(plan.members, static_cast<std::size_t>(o.prev_max));
  const std::size_t anchors = plan.members.size();
  const int prev_min = options.preset == Preset::Thesis
                           ? o.prev_min
                           : prev_group_min(o, options.preset, in_view(charting, c0, ahead), fewest_anchors(options));
  if (!plan.root() && static_cast<int>(anchors) < prev_min) {
    // Too few mapped points in view: the thesis's algorithm cannot place a group here. A
    // provisional root places it on its members' provisional positions instead.
    if (!options.provisional_root || !level.lowest) return no_group();
    plan.registration = Registration::WorldPositions;
  }

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
    candidate(n, id);
  }
  if (!has_c || static_cast<int>(ranked_.size()) < o.next_min) return no_group();
  rank(plan.members);
  plan.anchor.assign(plan.members.size(), false);
  std::fill(plan.anchor.begin(), plan.anchor.begin() + static_cast<std::ptrdiff_t>(anchors), true);
  if (o.binning && !keep_static(plan, c, c0, k, o, fewest_anchors(options), points, options.binning, outcome))
    return no_group();

  if (plan.root()) {  // three members with a place in the world frame fix the group's
    auto placed = [&](Registration r) {
      return std::count_if(plan.members.begin(), plan.members.end(), [&](PointId id) {
        const RltPoint& p = points[id];
        return r == Registration::FirstObservations ? p.first_observation.iteration == level.first_iteration
                                                    : p.has_global || p.has_provisional;
      });
    };
    if (placed(plan.registration) < 3 && plan.registration == Registration::FirstObservations &&
        options.provisional_root && level.lowest)
      plan.registration = Registration::WorldPositions;
    if (placed(plan.registration) < 3) return no_group();
  }

  const auto basis = select_basis(basis_positions(plan.members, points, c0, k), options.basis, options.min_basis_ratio);
  if (!basis) return no_group();
  plan.basis = *basis;
  outcome.plan = std::move(plan);
  return outcome;
}

PlanOutcome GroupPlanner::plan_level3(PointId c, int k, const std::vector<RltPoint>& points, RltPointCharting& charting,
                                      const PointSlamOptions& options) {
  PlanOutcome outcome;
  const Level3Options& o = options.level3;
  const RltPoint& cp = points[c];
  // The first visible run of c, whole: [s, e].
  const int s = cp.interval.first();
  const int e = visible_run_end(cp.interval, o.gap);
  if (s < charting.oldest()) return outcome;  // its run is older than the charting remembers

  // Everything seen in [s, e]: the mapped points, which register the group (level-3 grouped
  // ones first, then final, then temporary: a level builds on the best map there is), and
  // the rest, each most seen in the run first.
  scratch_.clear();
  charting.enumerate_unique(s, e, scratch_);
  std::vector<PointId> known, fresh;
  ranked_.clear();
  for (PointId id : scratch_) {
    const RltPoint& p = points[id];
    if (id == c || !p.on_map()) continue;
    const int level = p.level3_grouped ? 2 : p.final_grouped ? 1 : 0;
    candidate(level * (span_of(s, e) + 1) + p.interval.count(s, e), id);
  }
  rank(known);
  ranked_.clear();
  for (PointId id : scratch_) {
    const RltPoint& p = points[id];
    if (id != c && !p.on_map() && !p.dynamic && !p.merged && !p.level3_grouped)
      candidate(p.interval.count(s, e), id);
  }
  rank(fresh);
  if (static_cast<int>(known.size()) < o.prev_min) return outcome;

  // Iterations of [s, e] in which every member so far was seen.
  const int span = span_of(s, e);
  std::vector<char> usable(static_cast<std::size_t>(span), 1);
  auto intersect = [&](const RltPoint& p, std::vector<char>& in) {
    int n = 0;
    for (int t = 0; t < span; ++t) n += in[t] = in[t] && p.interval.contains(s + t);
    return n;
  };
  GroupPlan plan;
  plan.members.push_back(c);
  plan.anchor.push_back(false);
  int used = intersect(cp, usable);
  for (int i = 0; i < o.prev_min; ++i) {  // the seed: c and the three best registering points
    plan.members.push_back(known[i]);
    plan.anchor.push_back(true);
    used = intersect(points[known[i]], usable);
  }
  // The rest, merged by count: a member is worth its lost iterations when the usable
  // observations (iterations x members) grow (thesis 6.5.5 step 4).
  std::size_t a = static_cast<std::size_t>(o.prev_min), b = 0;
  std::vector<char> trial;
  while (a < known.size() || b < fresh.size()) {
    const bool take_known = b >= fresh.size() || (a < known.size() && points[known[a]].interval.count(s, e) >=
                                                                          points[fresh[b]].interval.count(s, e));
    const PointId x = take_known ? known[a++] : fresh[b++];
    trial = usable;
    const int now = intersect(points[x], trial);
    const auto m = static_cast<long long>(plan.members.size());
    if (static_cast<long long>(now) * (m + 1) <= static_cast<long long>(used) * m) continue;
    usable.swap(trial);
    used = now;
    plan.members.push_back(x);
    plan.anchor.push_back(take_known);
  }
  if (used == 0) return outcome;

  GroupLevelOptions level;  // what keep_static needs of a level
  level.next_min = 1;
  level.binning = o.binning;
  if (o.binning && !keep_static(plan, c, s, k, level, 3, points, options.binning, outcome)) return outcome;
  const auto basis = select_basis(basis_positions(plan.members, points, s, e), options.basis, options.min_basis_ratio);
  if (!basis) return outcome;
  plan.basis = *basis;
  outcome.plan = std::move(plan);
  return outcome;
}

}  // namespace relslam::point
