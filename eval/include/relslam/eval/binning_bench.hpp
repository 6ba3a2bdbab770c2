#pragma once
// The synthetic RltBinning benchmark S-BIN (thesis 6.5.3, Figs 111-116; spec 8.6): pairwise
// comparisons against the number of points, for shares of uncorrelated points, with and
// without the priority heuristic.

#include "relslam/core/option_issue.hpp"
#include "relslam/point/rlt_binning.hpp"

#include <cstdint>
#include <filesystem>
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

struct BinningBenchRow {
  int n = 0;
  double percent = 0;  // uncorrelated share; the correlated mix reports 50
  const char* variant = "uncorrelated";  // or "correlated"
  point::BinPairing pairing = point::BinPairing::Disjoint;
  bool heuristic = true;
  int seed = 0;
  int comparisons = 0;
  int highest_bin = 0;
  double threshold = 0;
  int wrongly_flagged = 0;  // static points left out of the largest bin
  int missed = 0;           // moving points inside it
};

// Every cell of the grid, both pairings, heuristic on and off; seeds from base_seed.
std::vector<BinningBenchRow> run_binning_bench(const BinningBenchOptions& options, std::uint64_t base_seed);
// binning_bench.csv (one row per binning) and binning_bench_means.csv (means over seeds, with
// the reference curves n - 1, n ln n, n log2 n, 3 n ln n and n^2 / 2).
void write_binning_bench(const std::filesystem::path& dir, const std::vector<BinningBenchRow>& rows);

}  // namespace relslam::eval
