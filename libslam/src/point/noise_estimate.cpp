#include "relslam/point/noise_estimate.hpp"

#include "relslam/point/noise_bounds.hpp"
#include "relslam/point/rlt_mapper.hpp"

#include <algorithm>
#include <cmath>

namespace relslam::point {
namespace {

// Iterations a pair's spread needs: fewer give a sample deviation too rough to rank [C].
constexpr int kMinPairSamples = 5;
// A pair counts when its mean distance is at least this many of its own deviations: closer, the
// distance of two noisy points is biased upwards and its spread is not sigma·sqrt(2) [C].
constexpr double kMinDistanceInDeviations = 5.0;

// Sample deviation of the distance between points a and b over the iterations of `on`, or
// nullopt with too few samples or too short a distance.
std::optional<double> distance_deviation(const RltPoint& a, const RltPoint& b, const RltInterval& on) {
  double sum = 0, sum_squares = 0;
  int n = 0;
  for (const RltInterval::Run& run : on.runs())
    for (int t = run.start; t <= run.end; ++t) {
      const Point* pa = a.observations.at(t);
      const Point* pb = b.observations.at(t);
      if (pa == nullptr || pb == nullptr) continue;  // the ring has dropped it
      const double d = (pa->p - pb->p).norm();
      sum += d, sum_squares += d * d, ++n;
    }
  if (n < kMinPairSamples) return std::nullopt;
  const double mean = sum / n;
  const double deviation = std::sqrt(std::max(0.0, (sum_squares - n * mean * mean) / (n - 1)));
  if (mean < kMinDistanceInDeviations * deviation) return std::nullopt;
  return deviation;
}

}  // namespace

std::optional<NoiseEstimate> estimate_noise_sigma(const std::vector<RltPoint>& points,
                                                  const std::vector<RltGroup>& groups) {
  std::vector<double> deviations;
  int groups_used = 0;
  for (const RltGroup& g : groups) {
    if (g.iterations_used() < kMinPairSamples) continue;
    const std::size_t before = deviations.size();
    PointId previous = kNone;
    for (PointId id : g.members()) {
      const RltPoint& p = points[id];
      if (p.dynamic || p.merged) continue;
      if (previous != kNone)
        if (const auto s = distance_deviation(points[previous], p, g.computed_on())) deviations.push_back(*s);
      previous = id;
    }
    groups_used += deviations.size() > before;
  }
  if (deviations.empty()) return std::nullopt;
  const auto middle = deviations.begin() + static_cast<std::ptrdiff_t>(deviations.size() / 2);
  std::nth_element(deviations.begin(), middle, deviations.end());
  return NoiseEstimate{.sigma = *middle / std::sqrt(2.0),
                       .pairs = static_cast<int>(deviations.size()),
                       .groups = groups_used};
}

std::optional<NoiseEstimate> estimate_noise_online(const PointSlamOptions& options,
                                                   const std::function<void(RltMapper&)>& feed) {
  std::optional<NoiseEstimate> estimate;
  for (int run = 1; run <= kNoisePilotRuns; ++run) {
    PointSlamOptions pilot = options;
    pilot.global_relaxation = GlobalRelaxation::Off;  // no joint solve: the estimate needs groups only
    if (estimate) apply_noise_bounds(noise_scaled_bounds(estimate->sigma), {}, pilot);
    RltMapper mapper(pilot);
    feed(mapper);
    auto next = estimate_noise_sigma(mapper.points(), mapper.groups());
    if (!next) break;  // keeps the estimate before, if any
    next->pilot_runs = run;
    const bool settled = estimate && std::abs(next->sigma - estimate->sigma) <= kNoiseSettled * estimate->sigma;
    estimate = next;
    // The thesis's bounds hold up to its noise: such an estimate needs no second look.
    if (settled || estimate->sigma <= kThesisNoiseSigma) break;
  }
  return estimate;
}

}  // namespace relslam::point
