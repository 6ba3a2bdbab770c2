#pragma once
// `relslam simulate`: run the simulator and write ground truth and observations.

#include "relslam/eval/cli/commands/scenario_command.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace relslam::eval {

using SimulateArgs = ScenarioCommandArgs;

void add_simulate(CLI::App& app, SimulateArgs& args);
int run_simulate(const SimulateArgs& args, const std::vector<std::string>& command_line);

}  // namespace relslam::eval
