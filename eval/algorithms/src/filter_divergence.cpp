#include "relslam/eval/algorithms/filter_divergence.hpp"

#include <cstdio>

namespace relslam::eval {
namespace {

// Three significant digits: the mean is compared with a bound, not reproduced.
std::string shown(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

}  // namespace

void FilterDivergence::add(int iteration, const StepInnovation& step) {
  if (!reason_.empty()) return;  // the first divergence stands
  if (step.pose_jump_sigma > options_.pose_jump_sigma) {
    reason_ = "diverged at iteration " + std::to_string(iteration) + ": its update moved the position " +
              shown(step.pose_jump_sigma) + " standard deviations from the prediction (bound " +
              shown(options_.pose_jump_sigma) + ")";
    return;
  }
  window_.emplace_back(iteration, step);
  if (static_cast<int>(window_.size()) > options_.window) window_.pop_front();
  // A full window only: the first few steps alone do not decide.
  if (static_cast<int>(window_.size()) < options_.window) return;
  double nis = 0;  // summed afresh: no drift from adding and taking away
  int dof = 0;
  for (const auto& [i, s] : window_) {
    nis += s.nis;
    dof += s.dof;
  }
  if (dof <= 0) return;
  // A NaN (an innovation covariance that is not positive definite) fails the test too.
  const double mean = nis / dof;
  if (mean <= options_.nis_bound) return;
  reason_ = "diverged at iteration " + std::to_string(iteration) + ": mean normalised innovation squared " +
            shown(mean) + " per degree of freedom over iterations " + std::to_string(window_.front().first) + " to " +
            std::to_string(iteration) + " (bound " + shown(options_.nis_bound) + ")";
}

std::string FilterDivergence::reason() const { return reason_; }

}  // namespace relslam::eval
