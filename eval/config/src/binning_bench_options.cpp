#include "relslam/eval/config/binning_bench_options.hpp"

namespace relslam::eval {

std::vector<OptionIssue> check(const BinningBenchOptions& o) {
  std::vector<OptionIssue> issues;
  for (int n : o.points) require_at_most(issues, "points", n, 100000);
  for (double p : o.percentages) {
    require_at_least(issues, "percentages", p, 0.0);
    require_at_most(issues, "percentages", p, 100.0);
  }
  require_at_least(issues, "seeds", o.seeds, 1);
  require_at_least(issues, "iterations", o.iterations, 5);
  require_at_least(issues, "static_sigma", o.static_sigma, 0.0);
  require_at_least(issues, "noisy_sigma", o.noisy_sigma, 0.0);
  require_at_least(issues, "correlated_step_sigma", o.correlated_step_sigma, 0.0);
  return issues;
}

}  // namespace relslam::eval
