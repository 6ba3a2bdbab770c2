#pragma once
// Many runs of one scenario with different overrides, in parallel: what sweeps and the EKF
// tuning are made of. Each run gets its own folder; a failing run is recorded, not fatal.

#include "relslam/eval/config/scenario_half.hpp"
#include "relslam/eval/metrics/run_summary.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace relslam::eval {

// One value of a grid axis: its label (in folder names and tables) and the --set texts it
// stands for — usually one, but an axis may tie keys together (yaw and pitch std. deviation).
struct AxisValue {
  std::string label;
  std::vector<std::string> overrides;
};
struct GridAxis {
  std::string name;
  std::vector<AxisValue> values;
};

// An axis setting one scenario key to each value (texts as --set takes them).
GridAxis key_axis(const std::string& key, const std::vector<std::string>& values);

struct BatchJob {
  std::filesystem::path folder;
  std::vector<std::string> overrides;  // --set texts, applied after the caller's own
  std::vector<std::string> labels;     // one per grid axis, in axis order
  int seed = 0;
};

// The cross product of the axes, for each seed: folders <out>/<axis>=<label>/.../seed-<n>.
std::vector<BatchJob> grid_jobs(const std::vector<GridAxis>& axes, const std::vector<int>& seeds,
                                const std::filesystem::path& out);

// Loads the scenario with every job's overrides, so a bad value or a cell with no algorithm to
// run fails before hours of runs (throws the InputError naming it).
void check_jobs_load(const std::string& scenario_file, const std::vector<std::string>& base_overrides,
                     const std::vector<BatchJob>& jobs);

struct BatchResult {
  BatchJob job;
  std::string error;             // empty when the run went through (its algorithms may still have failed)
  std::vector<SummaryRow> rows;  // per algorithm, then the relative_point/ekf6d ratio row when both ran
  // The half the run's scenario fed (half_of its kind), once it was loaded: which columns its
  // rows are tabulated in. None when the run never got that far.
  std::optional<ScenarioHalf> half = std::nullopt;
};

// Runs every job (relslam run semantics: simulate and run the algorithms into job.folder) on
// `threads` workers, showing progress. Results are in job order whatever the scheduling.
std::vector<BatchResult> run_batch(const std::string& scenario_file, const std::vector<std::string>& base_overrides,
                                   const std::vector<BatchJob>& jobs, int threads, bool progress,
                                   const std::vector<std::string>& command_line);

}  // namespace relslam::eval
