#include "relslam/point/point_matching.hpp"

#include "relslam/point/rlt_icp.hpp"

#include <algorithm>
#include <cmath>

namespace relslam::point {
namespace {}  // namespace

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
  for (const LocalCandidate& c : candidates) {
    const Eigen::Vector3d p = options_.compensate_motion ? predicted_motion(c.iteration, k) * c.p : c.p;
    if (c.id >= static_cast<PointId>(slot_.size())) slot_.resize(static_cast<std::size_t>(c.id) * 2 + 16, 0);
    slot_[c.id] = static_cast<int>(predicted_.size());
    predicted_.push_back({c.id, p});
  }
  local_->build(predicted_);
}

void PointMatcher::assign_greedily(int& counter) {
  // The thesis scores a match 100·(1 - d/bound) (6.2.1); ordering by the distance itself is the
  // same order without the rounding, which would make near-equal candidates tie.
  std::sort(pairs_.begin(), pairs_.end(), [](const Pair& a, const Pair& b) {
    if (a.distance != b.distance) return a.distance < b.distance;
    if (a.observation != b.observation) return a.observation < b.observation;
    return a.id < b.id;
  });
  for (const Pair& c : pairs_) {
    if (result_.assigned[c.observation] != kNone || taken(c.id)) continue;
    result_.assigned[c.observation] = c.id;
    if (c.id >= static_cast<PointId>(taken_.size())) taken_.resize(static_cast<std::size_t>(c.id) * 2 + 16, 0u);
    taken_[c.id] = stamp_;
    ++counter;
  }
}

void PointMatcher::match_local(const std::vector<Eigen::Vector3d>& observations, double bound) {
  if (++stamp_ == 0) {
    std::fill(taken_.begin(), taken_.end(), 0u);
    stamp_ = 1;
  }
  result_.assigned.assign(observations.size(), kNone);
  result_.local = 0;
  pairs_.clear();
  for (int i = 0; i < static_cast<int>(observations.size()); ++i)
    for (const spatial::IndexedPoint& c : local_->query(observations[i])) {
      const double d = (observations[i] - c.p).norm();
      if (d <= bound) pairs_.push_back({d, i, c.id});
    }
  assign_greedily(result_.local);
}

std::optional<Rigid3> PointMatcher::robust_motion(const std::vector<Eigen::Vector3d>& observations) const {
  // Pairs (predicted candidate -> observation); the fit is the correction to the prediction.
  std::vector<Eigen::Vector3d> from, to;
  for (std::size_t i = 0; i < observations.size(); ++i) {
    if (result_.assigned[i] == kNone) continue;
    from.push_back(predicted_[slot_[result_.assigned[i]]].p);
    to.push_back(observations[i]);
  }
  auto fit = rlt_icp(from, to);
  if (!fit) return std::nullopt;
  std::vector<double> residuals;
  for (std::size_t i = 0; i < from.size(); ++i) residuals.push_back((*fit * from[i] - to[i]).norm());
  std::vector<double> sorted = residuals;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double cut = options_.motion_outlier_cut * sorted[sorted.size() / 2] + 1e-12;
  std::vector<Eigen::Vector3d> kept_from, kept_to;
  for (std::size_t i = 0; i < from.size(); ++i)
    if (residuals[i] <= cut) kept_from.push_back(from[i]), kept_to.push_back(to[i]);
  return rlt_icp(kept_from, kept_to);
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
      for (spatial::IndexedPoint& p : predicted_) p.p = *correction * p.p;
      local_->build(predicted_);
      match_local(observations, options_.compensated_bound);
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
