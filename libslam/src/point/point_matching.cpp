#include "relslam/point/point_matching.hpp"

#include "relslam/point/rlt_icp.hpp"
#include "relslam/spatial/make_local_index.hpp"

#include <algorithm>
#include <cmath>

namespace relslam::point {
namespace {

// The second, motion-compensated pass reuses the first pass instead of rebuilding the local
// index over the moved candidates: it re-measures the first pass's pairs when the correction
// moved no candidate further than the gap between the bounds, else it queries the first index
// with each observation moved back by the correction. Either is exact up to rounding (~1e-13
// units at the frustum's 100-unit range), which this margin covers [C].
constexpr double kReuseMargin = 1e-6;

}  // namespace

const Eigen::Vector3d* global_match_position(const RltPoint& p, bool match_unmapped) {
  if (p.dynamic || p.merged) return nullptr;  // movers and merged shells are never matched globally
  if (p.has_global) return &p.global;
  if (match_unmapped && p.has_provisional) return &p.provisional;
  return nullptr;
}

PointMatcher::PointMatcher(const PointSlamOptions& options)
    : options_(options),
      local_(spatial::make_local_index(
          options.local_index,
          options.local_index == spatial::LocalIndexKind::Octree ? options.octree_cell_size : options.local_cell_size,
          options.local_bound)) {}

Rigid3 PointMatcher::predicted_motion(int from, int to) const {
  // Compose the stored steps from+1 .. to; a step without an estimate repeats the newest one
  // before it (constant velocity), the identity before anything is known.
  Rigid3 total = Rigid3::identity();
  Rigid3 step = Rigid3::identity();
  for (int t = from + 1; t <= to; ++t) {
    if (t == current_ && measured_step_) {
      step = *measured_step_;
    } else {
      for (const auto& [iteration, motion] : motions_)
        if (iteration <= t) {
          step = motion;
          break;
        }
    }
    total = step * total;
  }
  return total;
}

void PointMatcher::prepare(const std::vector<LocalCandidate>& candidates, int k,
                           const std::optional<Rigid3>& odometry) {
  current_ = k;
  measured_step_ = odometry ? std::optional(odometry->inverse()) : std::nullopt;
  predicted_.clear();
  // Candidates come from the last match_look_back iterations: one prediction per iteration,
  // not per candidate (the composition is the same, so is every predicted position).
  motion_from_.assign(static_cast<std::size_t>(options_.match_look_back) + 1, std::nullopt);
  for (const LocalCandidate& c : candidates) {
    Eigen::Vector3d p = c.p;
    if (options_.compensate_motion) {
      const auto back = static_cast<std::size_t>(k - c.iteration);
      std::optional<Rigid3>* cached = back < motion_from_.size() ? &motion_from_[back] : nullptr;
      if (cached && !*cached) *cached = predicted_motion(c.iteration, k);
      p = (cached ? **cached : predicted_motion(c.iteration, k)) * c.p;
    }
    if (c.id >= static_cast<PointId>(slot_.size())) slot_.resize(static_cast<std::size_t>(c.id) * 2 + 16, 0);
    slot_[c.id] = static_cast<int>(predicted_.size());
    predicted_.push_back({c.id, p});
  }
  local_->build(predicted_);
}

void PointMatcher::assign_greedily(int& counter) {
  // A pair that is both its observation's only pair and its point's only pair meets no rival:
  // closest-first assignment takes it whenever its turn comes, unless the point was taken by
  // an earlier pass. Only the contested rest needs the order.
  // pairs_ arrive grouped by observation.
  for (const Pair& c : pairs_) {
    if (c.id >= static_cast<PointId>(claims_.size())) claims_.resize(static_cast<std::size_t>(c.id) * 2 + 16, 0);
    ++claims_[c.id];
  }
  std::size_t contested = 0;
  int previous_observation = -1;
  for (std::size_t i = 0; i < pairs_.size(); ++i) {
    const Pair c = pairs_[i];  // pairs_[i] may be overwritten below, pairs_[i + 1] not yet
    const bool alone = previous_observation != c.observation &&
                       (i + 1 == pairs_.size() || pairs_[i + 1].observation != c.observation);
    previous_observation = c.observation;
    if (alone && claims_[c.id] == 1) {
      take(c, counter);
      claims_[c.id] = 0;
    } else {
      pairs_[contested++] = c;
    }
  }
  pairs_.resize(contested);
  for (const Pair& c : pairs_) claims_[c.id] = 0;
  // The thesis scores a match 100·(1 - d/bound) (6.2.1); ordering by the distance itself is the
  // same order without the rounding, which would make near-equal candidates tie.
  std::sort(pairs_.begin(), pairs_.end(), [](const Pair& a, const Pair& b) {
    if (a.distance != b.distance) return a.distance < b.distance;
    if (a.observation != b.observation) return a.observation < b.observation;
    return a.id < b.id;
  });
  for (const Pair& c : pairs_) take(c, counter);
}

void PointMatcher::take(const Pair& c, int& counter) {
  if (result_.assigned[c.observation] != kNone || taken(c.id)) return;
  result_.assigned[c.observation] = c.id;
  if (c.id >= static_cast<PointId>(taken_.size())) taken_.resize(static_cast<std::size_t>(c.id) * 2 + 16, 0u);
  taken_[c.id] = stamp_;
  ++counter;
}

void PointMatcher::begin_local_pass(std::size_t observations) {
  if (++stamp_ == 0) {
    std::fill(taken_.begin(), taken_.end(), 0u);
    stamp_ = 1;
  }
  result_.assigned.assign(observations, kNone);
  result_.local = 0;
  pairs_.clear();
}

void PointMatcher::add_pair(const Eigen::Vector3d& observation, int i, PointId id, const Eigen::Vector3d& candidate,
                            double bound) {
  // norm() is sqrt(squaredNorm()): the same distance, the root taken only for near candidates.
  const double d2 = (observation - candidate).squaredNorm();
  if (d2 > bound * bound * (1.0 + 1e-9)) return;
  const double d = std::sqrt(d2);
  if (d <= bound) pairs_.push_back({d, i, id});
}

void PointMatcher::match_local(const std::vector<Eigen::Vector3d>& observations, double bound,
                               const Rigid3* candidates_T_built) {
  begin_local_pass(observations.size());
  for (int i = 0; i < static_cast<int>(observations.size()); ++i) {
    // The index holds the candidates as built; moved since, they are found where the inverse
    // motion puts the observation, and measured where they are now.
    const Eigen::Vector3d q = candidates_T_built ? candidates_T_built->inverse_apply(observations[i]) : observations[i];
    for (const spatial::IndexedPoint& c : local_->query(q))
      add_pair(observations[i], i, c.id, candidates_T_built ? predicted_[slot_[c.id]].p : c.p, bound);
  }
  if (!candidates_T_built) first_pairs_ = pairs_;  // what rematch_local may start from
  assign_greedily(result_.local);
}

void PointMatcher::rematch_local(const std::vector<Eigen::Vector3d>& observations, double bound) {
  begin_local_pass(observations.size());
  for (const Pair& c : first_pairs_)
    add_pair(observations[c.observation], c.observation, c.id, predicted_[slot_[c.id]].p, bound);
  assign_greedily(result_.local);
}

std::optional<Rigid3> PointMatcher::robust_motion(const std::vector<Eigen::Vector3d>& observations) {
  // Pairs (predicted candidate -> observation); the fit is the correction to the prediction.
  std::vector<Eigen::Vector3d>&from = from_, &to = to_;
  from.clear();
  to.clear();
  for (std::size_t i = 0; i < observations.size(); ++i) {
    if (result_.assigned[i] == kNone) continue;
    from.push_back(predicted_[slot_[result_.assigned[i]]].p);
    to.push_back(observations[i]);
  }
  auto fit = rlt_icp(from, to);
  if (!fit) return std::nullopt;
  residuals_.clear();
  for (std::size_t i = 0; i < from.size(); ++i) residuals_.push_back((*fit * from[i] - to[i]).norm());
  std::vector<double>& sorted = sorted_residuals_;
  sorted.assign(residuals_.begin(), residuals_.end());
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double cut = options_.motion_outlier_cut * sorted[sorted.size() / 2] + 1e-12;
  // The kept pairs, compacted in place (order kept: the fit sums in it).
  std::size_t kept = 0;
  for (std::size_t i = 0; i < from.size(); ++i)
    if (residuals_[i] <= cut) from[kept] = from[i], to[kept] = to[i], ++kept;
  return rlt_icp(std::span(from).first(kept), std::span(to).first(kept));
}

const MatchResult& PointMatcher::match(const std::vector<Eigen::Vector3d>& observations, int k,
                                       spatial::GlobalIndex& global, const std::vector<RltPoint>& points,
                                       const Rigid3& world_T_previous) {
  // Local, untransformed (thesis 6.2.5): the candidates predicted by the recent motion.
  match_local(observations, options_.local_bound);
  result_.motion = predicted_motion(k - 1, k);
  result_.motion_estimated = false;
  if (options_.compensate_motion) {
    // Deviation (beyond the thesis): fit the frame-to-frame motion to these matches, move the
    // candidates by it and match again within the much tighter noise-level bound. Two
    // landmarks closer together than a frame's motion can then no longer swap.
    if (const auto correction = robust_motion(observations)) {
      double moved = 0;  // the farthest any candidate moved
      for (spatial::IndexedPoint& p : predicted_) {
        const Eigen::Vector3d corrected = *correction * p.p;
        moved = std::max(moved, (corrected - p.p).norm());
        p.p = corrected;
      }
      // A candidate within compensated_bound now was within compensated_bound + moved before,
      // so when that is inside local_bound the first pass found every pair already (the usual
      // case: the correction is small, Deviation of compensate_motion).
      if (options_.compensated_bound + moved + kReuseMargin <= options_.local_bound) {
        rematch_local(observations, options_.compensated_bound);
      } else if (options_.compensated_bound + kReuseMargin <= options_.local_bound) {
        match_local(observations, options_.compensated_bound, &*correction);
      } else {
        local_->build(predicted_);
        match_local(observations, options_.compensated_bound);
      }
      result_.motion = *correction * result_.motion;
      result_.motion_estimated = true;
    }
    while (!motions_.empty() && motions_.back().first <= k - options_.match_look_back - 1) motions_.pop_back();
    if (result_.motion_estimated || measured_step_) motions_.emplace_front(k, result_.motion);
  }

  // Global (thesis 6.5.1): the current position transforms the rest onto the map.
  const Rigid3 world_T_current = world_T_previous * result_.motion.inverse();
  result_.global = 0;
  pairs_.clear();
  for (int i = 0; i < static_cast<int>(observations.size()); ++i) {
    if (result_.assigned[i] != kNone) continue;
    const Eigen::Vector3d g = world_T_current * observations[i];
    for (PointId id : global.query(g)) {
      const RltPoint& p = points[id];
      if (p.last_iteration() >= k - options_.match_look_back) continue;  // local matching's job
      const Eigen::Vector3d* position = global_match_position(p, options_.match_unmapped);
      if (!position) continue;
      const double d = (g - *position).norm();
      if (d <= options_.global_bound) pairs_.push_back({d, i, id});
    }
  }
  assign_greedily(result_.global);
  return result_;
}

}  // namespace relslam::point
