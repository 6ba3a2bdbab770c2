#pragma once
// `relslam em-bench`: the plane-extraction test bench of thesis Figs 55-61 (E30), or with
// --compare every extractor on a scenario's identical point frames (E29).

#include "relslam/eval/cli/commands/scenario_command.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace relslam::eval {

struct EmBenchArgs : ScenarioCommandArgs {
  int seeds = 5;  // seeds per case [C]
  bool compare = false;  // E29: the scenario's own point frames through every extractor instead
};

void add_em_bench(CLI::App& app, EmBenchArgs& args);
int run_em_bench_command(const EmBenchArgs& args, const std::vector<std::string>& command_line);

}  // namespace relslam::eval
