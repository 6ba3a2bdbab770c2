#pragma once
// A sweep written down instead of run (relslam sweep --emit): the resolved grid (plan.json)
// and one `relslam run` command line per cell (commands.txt), for engines such as GNU parallel
// or Slurm to run anywhere; plan.json is also what --aggregate reads to find the cells again.

#include "relslam/eval/experiments/batch.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace relslam::eval {

struct SweepPlan {
  std::string scenario;          // absolute: the commands run in the sweep folder, maybe on another host
  std::vector<std::string> set;  // the --set texts every run gets first
  std::vector<GridAxis> axes;
  std::vector<int> seeds;
  std::vector<BatchJob> jobs;  // folders below the sweep folder, as grid_jobs made them
};

// plan.json in `dir` (job folders relative to `dir`).
void write_plan(const std::filesystem::path& dir, const SweepPlan& plan);
// plan.json of `dir`, job folders below `dir` again. Throws InputError when it is missing or bad.
SweepPlan read_plan(const std::filesystem::path& dir);

// The shell command line of one cell, run from the sweep folder `dir`:
// relslam run <scenario> --set ... --set seed=<n> --out <cell folder> --force --quiet.
// Its --set texts are those the local sweep applies, in the same order, so the cell is the same.
std::string run_command(const std::filesystem::path& dir, const SweepPlan& plan, const BatchJob& job);
// commands.txt in `dir`: line i is the command of job i (1-based, as Slurm array tasks count).
void write_commands(const std::filesystem::path& dir, const SweepPlan& plan);

}  // namespace relslam::eval
