#pragma once
// `relslam bench-binning`: the synthetic RltBinning benchmark S-BIN (Figs 111-116).

#include "relslam/eval/cli/commands/scenario_command.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace relslam::eval {

using BenchBinningArgs = ScenarioCommandArgs;

void add_bench_binning(CLI::App& app, BenchBinningArgs& args);
int run_bench_binning(const BenchBinningArgs& args, const std::vector<std::string>& command_line);

}  // namespace relslam::eval
