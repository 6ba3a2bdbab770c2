#include "algorithm_set.hpp"

#include <algorithm>

namespace relslam::eval {

AlgorithmSet::AlgorithmSet(const Scenario& scenario, const LandmarkTruth& truth, const RangeBearingSensor& sensor,
                           const std::filesystem::path& out)
    : out_(out) {
  for (const std::string& name : scenario.algorithms) runs_.push_back(make_algorithm_run(name, scenario, truth, sensor, out));
}

void AlgorithmSet::step(const ObservationFrame& observation, const TruthFrame& truth) {
  for (auto& run : runs_) run->step(observation, truth);
}

void AlgorithmSet::finish(ExperimentResult& result) {
  for (auto& run : runs_) result.rows.push_back(run->finish());
  // The Relative Point / EKF ratios, over the iterations both processed: against the 6D EKF,
  // or else the planar one with odometry.
  auto index_of = [&](const char* name) {
    for (std::size_t i = 0; i < runs_.size(); ++i)
      if (runs_[i]->name() == name) return static_cast<int>(i);
    return -1;
  };
  const int rp = index_of("relative_point");
  int ekf = index_of("ekf6d");
  if (ekf < 0) ekf = index_of("ekf2d");
  if (rp >= 0 && ekf >= 0) {
    const int common = std::min(result.rows[rp].iterations, result.rows[ekf].iterations);
    if (common > 0) result.ratio = ratio_row(runs_[rp]->summary_over(common), runs_[ekf]->summary_over(common));
  }
  write_summary(out_ / "summary.csv", result.rows, result.ratio);
}

}  // namespace relslam::eval
