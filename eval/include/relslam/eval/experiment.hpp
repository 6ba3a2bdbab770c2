#pragma once
// An experiment: one observation stream (simulated, or read from an MRPT rawlog) fed to every
// algorithm of a scenario, each scored against whatever truth there is.

#include "relslam/eval/run_summary.hpp"
#include "relslam/eval/scenario.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <vector>

namespace relslam::eval {

struct ExperimentResult {
  std::vector<SummaryRow> rows;     // one per algorithm
  std::optional<SummaryRow> ratio;  // relative_point/ekf6d, when both ran
  int iterations = 0;
  double seconds = 0;
  nlohmann::json source;            // what the observations were: manifest material
};

// Simulates the scenario into `out` (the files of relslam simulate) and runs its algorithms.
ExperimentResult simulate_and_run(const LoadedScenario& loaded, const std::filesystem::path& out, bool progress);

// The observations of an MRPT rawlog, with optional ground truth in MRPT's text formats.
struct RawlogSource {
  std::filesystem::path rawlog;
  std::optional<std::filesystem::path> truth_path;       // one row per frame
  std::optional<std::filesystem::path> truth_landmarks;
};
ExperimentResult run_on_rawlog(const LoadedScenario& loaded, const RawlogSource& source, const std::filesystem::path& out,
                               bool progress);

// The results table printed after a run.
void print_results(const ExperimentResult& result, const std::string& title);

}  // namespace relslam::eval
