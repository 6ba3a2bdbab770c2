#pragma once
// Internal to relslam_eval: every algorithm of a scenario, fed the same frames, writing one
// folder each and summary.csv. Shared by the simulated, rawlog and Victoria Park experiments.

#include "relslam/eval/algorithm_run.hpp"
#include "relslam/eval/experiment.hpp"
#include "relslam/eval/landmark_truth.hpp"
#include "relslam/eval/rawlog.hpp"

#include <filesystem>
#include <memory>
#include <vector>

namespace relslam::eval {

class AlgorithmSet {
 public:
  AlgorithmSet(const Scenario& scenario, const LandmarkTruth& truth, const RangeBearingSensor& sensor,
               const std::filesystem::path& out);
  void step(const ObservationFrame& observation, const TruthFrame& truth);
  // Closes every run, fills result.rows and result.ratio, writes summary.csv.
  void finish(ExperimentResult& result);
  const std::vector<std::unique_ptr<AlgorithmRun>>& runs() const { return runs_; }

 private:
  std::filesystem::path out_;
  std::vector<std::unique_ptr<AlgorithmRun>> runs_;
};

}  // namespace relslam::eval
