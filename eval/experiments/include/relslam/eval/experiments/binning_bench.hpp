#pragma once
// The synthetic RltBinning benchmark S-BIN (thesis 6.5.3, Figs 111-116): pairwise
// comparisons against the number of points, for shares of uncorrelated points, with and
// without the priority heuristic.

#include "relslam/eval/config/binning_bench_options.hpp"
#include "relslam/point/rlt_binning.hpp"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace relslam::eval {

struct BinningBenchRow {
  int n = 0;
  double percent = 0;                    // uncorrelated share; the correlated mix reports 50
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
