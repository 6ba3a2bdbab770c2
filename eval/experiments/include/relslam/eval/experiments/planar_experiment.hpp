#pragma once
// A planar experiment (scenario kind "planar"): one plane frame source fed to every plane
// algorithm of the scenario, each recorded and scored against the true walls, into one run
// folder: a sub-folder per algorithm and summary.csv (the counterpart of experiment.hpp).

#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/experiment_result.hpp"
#include "relslam/eval/experiments/plane_recorder.hpp"
#include "relslam/eval/sources/plane_frame_source.hpp"

#include <filesystem>
#include <memory>
#include <vector>

namespace relslam::eval {

class PlanarExperiment {
 public:
  // One recorder per algorithm of the scenario, writing into out/<name>/.
  PlanarExperiment(const LoadedScenario& loaded, PlaneFrameSource& source, const std::filesystem::path& out);
  // Streams every frame through every algorithm (progress on stderr), then writes summary.csv.
  ExperimentResult run(bool progress);
  const std::vector<std::unique_ptr<PlaneRecorder>>& recorders() const { return recorders_; }

 private:
  PlaneFrameSource& source_;
  std::filesystem::path out_;
  OutputOptions output_;  // the reference algorithm and revisits scored in summary.csv
  std::vector<std::unique_ptr<PlaneRecorder>> recorders_;
};

// Simulates the planar scenario into `out` (the files of relslam simulate) and runs its
// algorithms; simulate_and_run() comes here for kind "planar".
ExperimentResult simulate_planar_and_run(const LoadedScenario& loaded, const std::filesystem::path& out,
                                         bool progress);

}  // namespace relslam::eval
