#pragma once
// Settings of the synthetic RltBinning benchmark S-BIN (thesis 6.5.3, Figs 111-116);
// describe() gives each field's key, help and checks (relslam/core/option_fields.hpp).

#include "relslam/core/option_fields.hpp"

#include <vector>

namespace relslam::eval {

struct BinningBenchOptions {
  // Points per binning (Fig 111's x axis) [C, thesis 6.5.3].
  std::vector<int> points = {20, 40, 60, 80, 100, 120, 140, 160, 180, 200};
  // Shares of uncorrelated points, percent: 0-90 in tens (Figs 111-115) and 41-49 (Fig 116).
  std::vector<double> percentages = {0, 10, 20, 30, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 60, 70, 80, 90};
  int seeds = 10;             // repetitions per cell [C]
  int iterations = 60;        // observations per point: one final look-ahead [C]
  double static_sigma = 0.1;  // per-axis jitter of every point, units [C]
  double noisy_sigma = 1.0;   // extra jitter of an uncorrelated point, units [C]
  // Fig 114's "corr" mix: 50 % static, 10 % uncorrelated, 4 groups of 10 % sharing a random walk.
  bool correlated = true;
  double correlated_step_sigma = 0.5;  // random-walk step of a correlated group, units [C]
};

// The scenario keys of BinningBenchOptions (binning_bench.*): help and checks per field.
void describe(OptionsOf<BinningBenchOptions> auto& o, auto& f) {
  f.field("points", o.points, "S-BIN: points per binning (Fig 111's x)", at_most(100000));
  f.field("percentages", o.percentages, "S-BIN: shares of uncorrelated points, percent", at_least(0.0), at_most(100.0));
  f.field("seeds", o.seeds, "S-BIN: repetitions per cell", at_least(1));
  f.field("iterations", o.iterations, "S-BIN: observations per point", at_least(5));
  f.field("static_sigma", o.static_sigma, "S-BIN: jitter of every point, units", at_least(0.0));
  f.field("noisy_sigma", o.noisy_sigma, "S-BIN: extra jitter of uncorrelated points, units", at_least(0.0));
  f.field("correlated", o.correlated, "S-BIN: add Fig 114's mix with 4 correlated groups");
  f.field("correlated_step_sigma", o.correlated_step_sigma, "S-BIN: random-walk step of a correlated group, units",
          at_least(0.0));
}

}  // namespace relslam::eval
