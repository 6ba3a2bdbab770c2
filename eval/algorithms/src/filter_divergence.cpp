#include "relslam/eval/algorithms/filter_divergence.hpp"

#include "relslam/eval/metrics/three_digits.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace relslam::eval {

void FilterDivergence::add(int iteration, const StepInnovation& step) {
  if (!reason_.empty()) return;  // the first divergence stands
  if (step.pose_jump_sigma > options_.pose_jump_sigma) {
    reason_ = "diverged at iteration " + std::to_string(iteration) + ": its update moved the position " +
              three_digits(step.pose_jump_sigma) + " standard deviations from the prediction (bound " +
              three_digits(options_.pose_jump_sigma) + ")";
    return;
  }
  window_.emplace_back(iteration, step);
  if (static_cast<int>(window_.size()) > std::max(options_.window, options_.long_window)) window_.pop_front();
  check_mean(iteration);
  if (reason_.empty()) check_median(iteration);
}

void FilterDivergence::check_median(int iteration) {
  if (static_cast<int>(window_.size()) < options_.long_window) return;
  std::vector<double> ratios;  // each step's NIS per degree of freedom; NaN counts as infinite
  for (auto s = window_.end() - options_.long_window; s != window_.end(); ++s)
    if (s->second.dof > 0)
      ratios.push_back(std::isnan(s->second.nis) ? std::numeric_limits<double>::infinity()
                                                 : s->second.nis / s->second.dof);
  if (2 * static_cast<int>(ratios.size()) < options_.long_window) return;
  const auto middle = ratios.begin() + static_cast<std::ptrdiff_t>(ratios.size() / 2);
  std::nth_element(ratios.begin(), middle, ratios.end());
  if (*middle <= options_.median_nis_bound) return;
  reason_ = "diverged at iteration " + std::to_string(iteration) +
            ": median normalised innovation squared per degree of freedom " + three_digits(*middle) + " over iterations " +
            std::to_string((window_.end() - options_.long_window)->first) + " to " + std::to_string(iteration) +
            " (bound " + three_digits(options_.median_nis_bound) + ")";
}

void FilterDivergence::check_mean(int iteration) {
  const int window = options_.window;
  const double bound = options_.nis_bound;
  // A full window only: the first few steps alone do not decide.
  if (static_cast<int>(window_.size()) < window) return;
  double nis = 0;  // summed afresh: no drift from adding and taking away
  int dof = 0;
  const auto first = window_.end() - window;
  for (auto s = first; s != window_.end(); ++s) {
    nis += s->second.nis;
    dof += s->second.dof;
  }
  if (dof <= 0) return;
  // A NaN (an innovation covariance that is not positive definite) fails the test too.
  const double mean = nis / dof;
  if (mean <= bound) return;
  reason_ = "diverged at iteration " + std::to_string(iteration) + ": mean normalised innovation squared " +
            three_digits(mean) + " per degree of freedom over iterations " + std::to_string(first->first) + " to " +
            std::to_string(iteration) + " (bound " + three_digits(bound) + ")";
}

std::string FilterDivergence::reason() const { return reason_; }

}  // namespace relslam::eval
