#include "relslam/eval/commands/scenario_command.hpp"

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

}  // namespace relslam::eval
