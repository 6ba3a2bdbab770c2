#pragma once
// `relslam bench-binning`: the synthetic RltBinning benchmark S-BIN (Figs 111-116).

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace relslam::eval {

struct BenchBinningArgs {
  std::string scenario;
  std::string out;
  std::vector<std::string> set;
  bool force = false;
  bool quiet = false;
};

void add_bench_binning(CLI::App& app, BenchBinningArgs& args);
int run_bench_binning(const BenchBinningArgs& args, const std::vector<std::string>& command_line);

}  // namespace relslam::eval
