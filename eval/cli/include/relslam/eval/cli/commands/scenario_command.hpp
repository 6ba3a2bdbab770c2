#pragma once
// What every command that runs a scenario into a run folder takes on the command line.

#include "relslam/eval/config/scenario_loading.hpp"

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

// The scenario file with the --set overrides, every key and every algorithm name checked
// (InputError at the offending line).
LoadedScenario load_checked(const std::string& file, const std::vector<std::string>& set);
// The same from JSON text named `name` in messages.
LoadedScenario parse_checked(const std::string& text, const std::string& name, const std::vector<std::string>& set);

}  // namespace relslam::eval
