#pragma once
// Every frame source a run may read, found by the scenario's kind and the input files given:
// the one place that decides which half of the workbench a run feeds. Each entry builds its
// source and runs the scenario's algorithms on it through the run skeleton (run_skeleton.hpp).
// Adding a source is one entry in source_registry.cpp.

#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/experiment_result.hpp"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace relslam::eval {

// The recorded observations and truth files a run was given (empty: not given); none, a
// simulation of the scenario's world.
struct RunInputs {
  std::filesystem::path rawlog;           // an MRPT rawlog (point half)
  std::filesystem::path planes;           // plane_observations.csv columns (plane half)
  std::filesystem::path truth_path;       // with either
  std::filesystem::path truth_landmarks;  // with rawlog
  std::filesystem::path truth_walls;      // with planes
};

struct SourceEntry {
  std::string name;  // what the docs call it
  std::string help;  // one line: what the frames are
  // Whether this source reads these inputs for this scenario; the first entry that does runs.
  std::function<bool(const Scenario& scenario, const RunInputs& inputs)> takes;
  // Builds the source, records what it simulates into `out`, and runs the algorithms on it.
  std::function<ExperimentResult(const LoadedScenario& loaded, const RunInputs& inputs,
                                 const std::filesystem::path& out, bool progress)>
      run;
};

const std::vector<SourceEntry>& source_registry();
// The entry that takes these inputs for this scenario (logic_error when none: the last entry
// takes everything).
const SourceEntry& source_for(const LoadedScenario& loaded, const RunInputs& inputs);
// source_for(loaded, inputs).run(loaded, inputs, out, progress).
ExperimentResult run_from_source(const LoadedScenario& loaded, const RunInputs& inputs,
                                 const std::filesystem::path& out, bool progress);
// Simulates the scenario's world into `out` (the files of relslam simulate) and runs its
// algorithms on it: run_from_source without recorded inputs.
ExperimentResult simulate_and_run(const LoadedScenario& loaded, const std::filesystem::path& out, bool progress);

}  // namespace relslam::eval
