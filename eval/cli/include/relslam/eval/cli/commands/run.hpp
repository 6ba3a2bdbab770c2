#pragma once
// `relslam run`: simulate a scenario and run its algorithms on the same observations.

#include "relslam/eval/cli/commands/scenario_command.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace relslam::eval {

struct RunArgs : ScenarioCommandArgs {
  std::string rawlog;           // observations from this rawlog instead of the simulator
  std::string truth_path;       // optional, with rawlog
  std::string truth_landmarks;  // optional, with rawlog
  std::string planes;           // plane observations from this file (plane_observations.csv columns)
  std::string truth_walls;      // optional, with planes
};

void add_run(CLI::App& app, RunArgs& args);
int run_run(const RunArgs& args, const std::vector<std::string>& command_line);

}  // namespace relslam::eval
