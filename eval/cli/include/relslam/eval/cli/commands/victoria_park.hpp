#pragma once
// `relslam victoria-park`: the scenario's algorithms on a window of the Victoria Park data set
// (thesis 6.8); `relslam convert victoria-park`: the data set as an MRPT rawlog.

#include "relslam/eval/cli/commands/scenario_command.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace relslam::eval {

struct VictoriaParkArgs : ScenarioCommandArgs {
  std::string data;     // the data folder (else $RELSLAM_VICTORIA_PARK, else ../shared/datasets/victoria_park)
  std::string window;   // overrides victoria_park.window
  bool bridge = false;  // relative_point.use_odometry = true
};

struct ConvertVictoriaParkArgs {
  std::string out;  // the rawlog to write
  std::string data;
  std::string window = "all";
  std::string scenario = "scenarios/victoria-park.json";  // its detection filter and laser model
  bool gzip = false;
  bool quiet = false;
};

void add_victoria_park(CLI::App& app, VictoriaParkArgs& args);
int run_victoria_park_command(const VictoriaParkArgs& args, const std::vector<std::string>& command_line);

// Adds `convert` with its `victoria-park` subcommand.
void add_convert(CLI::App& app, ConvertVictoriaParkArgs& args);
int run_convert_victoria_park(const ConvertVictoriaParkArgs& args);

}  // namespace relslam::eval
