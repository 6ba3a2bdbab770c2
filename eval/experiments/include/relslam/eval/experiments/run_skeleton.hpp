#pragma once
// The one run every experiment goes through, whatever its frames and algorithms: one frame
// source fed to every algorithm of a scenario, each through its recorder (timing, status, input
// digest, trajectory, scores), with progress and interruption, then summary.csv. The family
// (algorithm_family.hpp) says which source, recorder and summary fields; nothing here does.

#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/algorithm_family.hpp"
#include "relslam/eval/experiments/experiment_result.hpp"
#include "relslam/eval/experiments/interruption.hpp"
#include "relslam/eval/experiments/require_algorithms.hpp"
#include "relslam/eval/io/progress.hpp"

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

namespace relslam::eval {

template <class Family>
class RunSkeleton {
 public:
  using Source = typename Family::Source;
  using Recorder = typename Family::Recorder;

  // One recorder per algorithm of the scenario, writing into out/<name>/.
  RunSkeleton(const LoadedScenario& loaded, Source& source, const std::filesystem::path& out)
      : source_(source), out_(out), output_(loaded.scenario.output) {
    require_algorithms(loaded);
    recorders_ = Family::recorders(loaded, source, out);
  }

  // Streams every frame through every algorithm (progress on stderr), then writes summary.csv.
  ExperimentResult run(bool progress) {
    const auto start = std::chrono::steady_clock::now();
    Progress bar(source_.label(), source_.frames(), progress);
    ExperimentResult result;
    result.half = Family::half;
    // Interrupted, the run finishes with the frames processed so far, every row says where it
    // was cut, and the command marks the manifest "interrupted".
    const std::optional<int> stopped_at = stream(bar);
    result.interrupted = stopped_at.has_value();
    for (auto& recorder : recorders_) result.rows.push_back(recorder->finish());
    if (stopped_at) mark_interrupted(result.rows, *stopped_at);
    Family::add_cross_scores(result.rows, recorders_, output_);
    result.ratio = Family::ratio(recorders_, result.rows);
    result.optimum_ratios = Family::floor_ratios(recorders_, result.rows);
    write_summary(out_ / "summary.csv", Family::summary_columns(), result.rows, result.ratio, result.optimum_ratios);
    bar.finish();
    result.iterations = static_cast<int>(source_.frames());
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.source = source_.describe();
    return result;
  }

  const std::vector<std::unique_ptr<Recorder>>& recorders() const { return recorders_; }

 private:
  // Every frame through every recorder. A signal (interruption.hpp) stops it between frames: it
  // returns the iteration it stopped at (the first not processed) then, and the recorders hold
  // the frames processed so far; nothing otherwise.
  std::optional<int> stream(Progress& bar) {
    int next = 0;
    try {
      source_.stream([&](const auto& observation, const auto&... with) {  // the truth, what was measured
        stop_if_interrupted();
        for (auto& recorder : recorders_) recorder->step(observation, with...);
        next = observation.iteration + 1;
        bar.update(next);
      });
    } catch (const RunInterrupted&) {
      return next;
    }
    return std::nullopt;
  }

  Source& source_;
  std::filesystem::path out_;
  OutputOptions output_;  // the reference algorithm and revisits scored across rows
  std::vector<std::unique_ptr<Recorder>> recorders_;
};

// The point half's experiment (simulated worlds, MRPT rawlogs, Victoria Park) and the plane
// half's (planar worlds, plane files).
using Experiment = RunSkeleton<PointFamily>;
using PlanarExperiment = RunSkeleton<PlaneFamily>;

}  // namespace relslam::eval
