#include "relslam/eval/experiments/planar_experiment.hpp"

#include "reference_scores.hpp"
#include "stream_to_recorders.hpp"

#include "relslam/eval/algorithms/registry.hpp"
#include "relslam/eval/experiments/interruption.hpp"
#include "relslam/eval/experiments/require_algorithms.hpp"
#include "relslam/eval/io/progress.hpp"
#include "relslam/eval/sources/planar_simulation_source.hpp"

#include <chrono>

namespace relslam::eval {

PlanarExperiment::PlanarExperiment(const LoadedScenario& loaded, PlaneFrameSource& source,
                                   const std::filesystem::path& out)
    : source_(source), out_(out), output_(loaded.scenario.output) {
  require_algorithms(loaded);
  const PlaneAlgorithmContext context{loaded.scenario, source.start()};
  for (const std::string& name : loaded.scenario.algorithms)
    recorders_.push_back(
        std::make_unique<PlaneRecorder>(make_plane_algorithm(name, context), source, out / name));
}

ExperimentResult PlanarExperiment::run(bool progress) {
  const auto start = std::chrono::steady_clock::now();
  Progress bar(source_.label(), source_.frames(), progress);
  ExperimentResult result;
  // Interrupted, the run finishes with the frames processed so far, every row says where it was
  // cut, and the command marks the manifest "interrupted".
  const std::optional<int> stopped_at = stream_to_recorders(source_, recorders_, bar);
  result.interrupted = stopped_at.has_value();
  for (auto& recorder : recorders_) result.rows.push_back(recorder->finish());
  if (stopped_at) mark_interrupted(result.rows, *stopped_at);
  add_reference_scores(result.rows, recorders_, output_);
  write_summary(out_ / "summary.csv", result.rows);
  bar.finish();
  result.iterations = static_cast<int>(source_.frames());
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.source = source_.describe();
  return result;
}

ExperimentResult simulate_planar_and_run(const LoadedScenario& loaded, const std::filesystem::path& out,
                                         bool progress) {
  require_algorithms(loaded);
  PlanarSimulationSource source(loaded);
  source.record_into(out);
  PlanarExperiment experiment(loaded, source, out);
  return experiment.run(progress);
}

}  // namespace relslam::eval
