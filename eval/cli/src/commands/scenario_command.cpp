#include "relslam/eval/cli/commands/scenario_command.hpp"

#include "relslam/eval/algorithms/registry.hpp"

namespace relslam::eval {

CLI::App* add_scenario_command(CLI::App& app, ScenarioCommandArgs& args, const std::string& name,
                               const std::string& summary, const std::string& description,
                               const std::string& scenario_example) {
  CLI::App* cmd = app.add_subcommand(name, summary);
  cmd->description(description);
  cmd->add_option("scenario", args.scenario, "Scenario file, e.g. " + scenario_example)->required();
  cmd->add_option("--out,-o", args.out, "Run folder to create (refused if it exists and is not empty)")->required();
  cmd->add_option("--set", args.set, "Override a scenario key, e.g. --set sim.density=50 (repeatable)");
  cmd->add_flag("--force", args.force, "Replace an earlier run in the --out folder");
  cmd->add_flag("--quiet,-q", args.quiet, "Print nothing but errors");
  return cmd;
}

LoadedScenario load_checked(const std::string& file, const std::vector<std::string>& set) {
  LoadedScenario loaded = load_with_overrides(file, set);
  check_algorithm_names(loaded);
  return loaded;
}

LoadedScenario parse_checked(const std::string& text, const std::string& name, const std::vector<std::string>& set) {
  LoadedScenario loaded = parse_scenario_with_overrides(text, name, set);
  check_algorithm_names(loaded);
  return loaded;
}

}  // namespace relslam::eval
