#pragma once
// An experiment: one frame source (simulated, an MRPT rawlog, Victoria Park) fed to every
// algorithm of a scenario, each recorded and scored against whatever truth there is, into one
// run folder: a sub-folder per algorithm and summary.csv.

#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/algorithm_recorder.hpp"
#include "relslam/eval/experiments/experiment_result.hpp"
#include "relslam/eval/sources/frame_source.hpp"
#include "relslam/eval/sources/rawlog_source.hpp"

#include <filesystem>
#include <memory>
#include <vector>

namespace relslam::eval {

class Experiment {
 public:
  // One recorder per algorithm of the scenario, writing into out/<name>/.
  Experiment(const LoadedScenario& loaded, FrameSource& source, const std::filesystem::path& out);
  // Streams every frame through every algorithm (progress on stderr), then writes summary.csv.
  ExperimentResult run(bool progress);
  const std::vector<std::unique_ptr<AlgorithmRecorder>>& recorders() const { return recorders_; }

 private:
  FrameSource& source_;
  std::filesystem::path out_;
  std::vector<std::unique_ptr<AlgorithmRecorder>> recorders_;
};

// Simulates the scenario into `out` (the files of relslam simulate) and runs its algorithms;
// point world or, for kind "planar", the planar world (planar_experiment.hpp).
ExperimentResult simulate_and_run(const LoadedScenario& loaded, const std::filesystem::path& out, bool progress);
// The observations of an MRPT rawlog, with optional ground truth in MRPT's text formats.
ExperimentResult run_on_rawlog(const LoadedScenario& loaded, const RawlogFiles& files, const std::filesystem::path& out,
                               bool progress);

// The results table printed after a run.
void print_results(const ExperimentResult& result, const std::string& title);

}  // namespace relslam::eval
