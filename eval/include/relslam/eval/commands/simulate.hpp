#pragma once
// `relslam simulate`: run the simulator and write ground truth and observations.

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace relslam::eval {

struct SimulateArgs {
  std::string scenario;          // path to scenarios/*.json
  std::string out;               // run folder
  std::vector<std::string> set;  // --set key=value, in order
  bool force = false;            // replace an earlier run in `out`
  bool quiet = false;            // no summary on stdout
};

void add_simulate(CLI::App& app, SimulateArgs& args);
int run_simulate(const SimulateArgs& args, const std::vector<std::string>& command_line);

}  // namespace relslam::eval
