#pragma once
// `relslam sweep`: a scenario over a grid of parameter values and seeds, in parallel, with
// mean, standard deviation and 95 % confidence interval over the seeds. Or, for grids larger than
// one machine, the same grid written out for GNU parallel or Slurm (--emit) and the tables made
// afterwards from the cells they ran (--aggregate).

#include "relslam/eval/cli/commands/scenario_command.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace relslam::eval {

struct SweepArgs : ScenarioCommandArgs {
  std::vector<std::string> params;  // key=v1,v2,...
  int seeds = 1;
  int jobs = 2;
  std::string emit;       // write the sweep into this folder as a plan and launchers, run nothing
  std::string aggregate;  // make the tables of this sweep folder from whatever cells it holds
  std::string resume;     // run the missing, failed and interrupted cells of this sweep folder
  std::string slurm_time = "01:00:00";
  std::string slurm_memory = "2G";
  int slurm_throttle = 8;
};

void add_sweep(CLI::App& app, SweepArgs& args);
int run_sweep(const SweepArgs& args, const std::vector<std::string>& command_line);

}  // namespace relslam::eval
