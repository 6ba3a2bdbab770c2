#pragma once
// What every command that runs a scenario into a run folder takes on the command line.

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace relslam::eval {

struct ScenarioCommandArgs {
  std::string scenario;          // path to scenarios/*.json
  std::string out;               // run folder
  std::vector<std::string> set;  // --set key=value, in order
  bool force = false;            // replace an earlier run in `out`
  bool quiet = false;            // no summary on stdout
};

// Adds the subcommand `name` with the shared options (scenario, --out, --set, --force, --quiet).
CLI::App* add_scenario_command(CLI::App& app, ScenarioCommandArgs& args, const std::string& name,
                               const std::string& summary, const std::string& description,
                               const std::string& scenario_example);

}  // namespace relslam::eval
