#pragma once
// `relslam run`: simulate a scenario and run its algorithms on the same observations.

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace relslam::eval {

struct RunArgs {
  std::string scenario;
  std::string out;
  std::vector<std::string> set;
  bool force = false;
  bool quiet = false;
};

void add_run(CLI::App& app, RunArgs& args);
int run_run(const RunArgs& args, const std::vector<std::string>& command_line);

}  // namespace relslam::eval
