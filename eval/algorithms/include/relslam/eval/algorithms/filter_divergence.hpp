#pragma once
// When a Kalman filter has diverged, without the truth: the mean normalised innovation squared
// of its associated observations over a sliding window against a bound, the median of each
// step's over a long window against another (a burst, a sustained excess), and each update's move
// of the position against a bound in standard deviations of the prediction
// (config/ekf_divergence_options.hpp says why). The first step over either bound names the
// iteration; the run's summary.csv status is then "lost: diverged at iteration N: ...", never
// "ok", whatever the filter does afterwards (a filter that lost its pose has built its map on
// it), and sweeps leave it out as they leave out failures.

#include "relslam/eval/config/ekf_divergence_options.hpp"

#include <deque>
#include <string>
#include <utility>

namespace relslam::eval {

// One step's innovations: the sum of nu^T S^-1 nu over the observations the filter associated
// to its map, and their degrees of freedom (components per observation times observations).
struct StepInnovation {
  double nis = 0;
  int dof = 0;
  // How far the update moved the position from the motion model's prediction, in standard
  // deviations of that prediction (sqrt of the Mahalanobis distance squared).
  double pose_jump_sigma = 0;
};

class FilterDivergence {
 public:
  explicit FilterDivergence(const EkfDivergenceOptions& options) : options_(options) {}
  // The step of `iteration`; steps come in order.
  void add(int iteration, const StepInnovation& step);
  // "" while the filter has not diverged, else e.g. "diverged at iteration 37: mean normalised
  // innovation squared 812 per degree of freedom over iterations 28 to 37 (bound 25)" or
  // "diverged at iteration 65: its update moved the position 42.7 standard deviations from the
  // prediction (bound 30)".
  std::string reason() const;

 private:
  // Whether the mean NIS per degree of freedom over the last `window` steps exceeds its bound,
  // or the median of the steps' NIS per degree of freedom over the last `long_window` steps
  // exceeds its own; each notes the reason if so.
  void check_mean(int iteration);
  void check_median(int iteration);

  EkfDivergenceOptions options_;
  std::deque<std::pair<int, StepInnovation>> window_;
  std::string reason_;
};

}  // namespace relslam::eval
