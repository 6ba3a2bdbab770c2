#pragma once
// Settings of the synthetic RltBinning benchmark S-BIN (thesis 6.5.3, Figs 111-116; spec 8.6).

#include "relslam/core/option_issue.hpp"

#include <vector>

namespace relslam::eval {

struct BinningBenchOptions {
  // Points per binning (Fig 111's x axis) [C, spec 8.6].
  std::vector<int> points = {20, 40, 60, 80, 100, 120, 140, 160, 180, 200};
  // Shares of uncorrelated points, percent: 0-90 in tens (Figs 111-115) and 41-49 (Fig 116).
  std::vector<double> percentages = {0, 10, 20, 30, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 60, 70, 80, 90};
  int seeds = 10;               // repetitions per cell [C]
  int iterations = 60;          // observations per point: one final look-ahead [C]
  double static_sigma = 0.1;    // per-axis jitter of every point, units [C]
  double noisy_sigma = 1.0;     // extra jitter of an uncorrelated point, units [C]
  // Fig 114's "corr" mix: 50 % static, 10 % uncorrelated, 4 groups of 10 % sharing a random walk.
  bool correlated = true;
  double correlated_step_sigma = 0.5;  // random-walk step of a correlated group, units [C]
};

// Every violated constraint, fields named as in the struct.
std::vector<OptionIssue> check(const BinningBenchOptions& options);

}  // namespace relslam::eval
