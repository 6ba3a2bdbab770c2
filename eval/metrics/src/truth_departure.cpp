#include "relslam/eval/metrics/truth_departure.hpp"

#include "relslam/eval/metrics/three_digits.hpp"

#include <algorithm>

namespace relslam::eval {

double path_extent(const std::vector<Eigen::Vector3d>& points) {
  if (points.empty()) return 0;
  Eigen::Vector3d lo = points.front(), hi = points.front();
  for (const Eigen::Vector3d& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

std::string truth_departure(const std::vector<PositionErrorAt>& errors, double extent) {
  const double bound = kTruthDepartureShare * extent;
  if (!(bound > 0)) return "";  // a path of no extent has no scale to measure by
  int in_a_row = 0;
  double worst = 0;
  for (const PositionErrorAt& e : errors) {
    // NaN is no error: not beyond the bound (it ends the run of departures like a missing pose).
    const bool beyond = e.error && *e.error > bound;
    in_a_row = beyond ? in_a_row + 1 : 0;
    worst = beyond ? std::max(worst, *e.error) : 0;
    if (in_a_row == kTruthDepartureIterations)
      return "left the truth at iteration " + std::to_string(e.iteration) + ": position error beyond " +
             three_digits(bound) + " (a tenth of the true path's extent of " + three_digits(extent) + ") for " +
             std::to_string(kTruthDepartureIterations) + " iterations in a row, " + three_digits(worst) + " at most";
  }
  return "";
}

}  // namespace relslam::eval
