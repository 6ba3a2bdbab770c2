#pragma once
// `relslam sweep`: a scenario over a grid of parameter values and seeds, in parallel, with
// mean, standard deviation and 95 % confidence interval over the seeds.

#include "relslam/eval/cli/commands/scenario_command.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace relslam::eval {

struct SweepArgs : ScenarioCommandArgs {
  std::vector<std::string> params;  // key=v1,v2,...
  int seeds = 1;
  int jobs = 2;
};

void add_sweep(CLI::App& app, SweepArgs& args);
int run_sweep(const SweepArgs& args, const std::vector<std::string>& command_line);

}  // namespace relslam::eval
