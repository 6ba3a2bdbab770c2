#include "relslam/eval/experiments/source_registry.hpp"

#include "relslam/eval/config/scenario_half.hpp"
#include "relslam/eval/experiments/experiment.hpp"
#include "relslam/eval/experiments/laser_experiment.hpp"
#include "relslam/eval/experiments/run_skeleton.hpp"
#include "relslam/eval/sources/planar_simulation_source.hpp"
#include "relslam/eval/sources/plane_file_source.hpp"
#include "relslam/eval/sources/simulation_source.hpp"

#include <optional>
#include <stdexcept>

namespace relslam::eval {
namespace {

std::optional<std::filesystem::path> given(const std::filesystem::path& file) {
  return file.empty() ? std::nullopt : std::optional<std::filesystem::path>(file);
}

// Simulates the scenario's world into `out` (the files of relslam simulate) and runs on it.
template <class Family, class Source>
ExperimentResult simulated(const LoadedScenario& loaded, const std::filesystem::path& out, bool progress) {
  require_algorithms(loaded);
  Source source(loaded);
  source.record_into(out);
  RunSkeleton<Family> run(loaded, source, out);
  return run.run(progress);
}

ExperimentResult plane_files(const LoadedScenario& loaded, const RunInputs& inputs, const std::filesystem::path& out,
                             bool progress) {
  if (!feeds_planes(loaded.scenario.kind))
    throw loaded.error("kind", "--planes feeds the planar half: the scenario must be of kind \"planar\"");
  PlaneFileSource source(PlaneFiles{inputs.planes, given(inputs.truth_path), given(inputs.truth_walls)});
  PlanarExperiment run(loaded, source, out);
  return run.run(progress);
}

}  // namespace

const std::vector<SourceEntry>& source_registry() {
  static const std::vector<SourceEntry> entries = {
      {"plane_file", "plane observations from a CSV file, with optional true path and walls (relslam run --planes)",
       [](const Scenario&, const RunInputs& in) { return !in.planes.empty(); }, plane_files},
      {"laser_rawlog", "2-D laser scans from an MRPT rawlog, their walls for the planar half (relslam run --rawlog, kind \"planar\")",
       [](const Scenario& s, const RunInputs& in) { return !in.rawlog.empty() && feeds_planes(s.kind); },
       [](const LoadedScenario& loaded, const RunInputs& in, const std::filesystem::path& out, bool progress) {
         return run_on_laser_rawlog(loaded, in.rawlog.string(), "--rawlog", out, progress);
       }},
      {"rawlog", "range-bearing observations from an MRPT rawlog, with optional truth (relslam run --rawlog)",
       [](const Scenario&, const RunInputs& in) { return !in.rawlog.empty(); },
       [](const LoadedScenario& loaded, const RunInputs& in, const std::filesystem::path& out, bool progress) {
         return run_on_rawlog(loaded, RawlogFiles{in.rawlog, given(in.truth_path), given(in.truth_landmarks)}, out,
                              progress);
       }},
      {"laser_scenario", "the 2-D laser log the planar scenario names (laser.rawlog)",
       [](const Scenario& s, const RunInputs&) { return feeds_planes(s.kind) && !s.laser.rawlog.empty(); },
       [](const LoadedScenario& loaded, const RunInputs&, const std::filesystem::path& out, bool progress) {
         return run_on_laser_rawlog(loaded, loaded.scenario.laser.rawlog, "laser.rawlog", out, progress);
       }},
      {"planar_simulation", "the planar world of walls, seen by the plane or point sensor (kind \"planar\")",
       [](const Scenario& s, const RunInputs&) { return feeds_planes(s.kind); },
       [](const LoadedScenario& loaded, const RunInputs&, const std::filesystem::path& out, bool progress) {
         return simulated<PlaneFamily, PlanarSimulationSource>(loaded, out, progress);
       }},
      {"simulation", "the simulated point world and path (kind \"simulation\")",
       [](const Scenario&, const RunInputs&) { return true; },
       [](const LoadedScenario& loaded, const RunInputs&, const std::filesystem::path& out, bool progress) {
         return simulated<PointFamily, SimulationSource>(loaded, out, progress);
       }},
  };
  return entries;
}

const SourceEntry& source_for(const LoadedScenario& loaded, const RunInputs& inputs) {
  for (const SourceEntry& entry : source_registry())
    if (entry.takes(loaded.scenario, inputs)) return entry;
  throw std::logic_error("source_for: no source takes these inputs");
}

ExperimentResult run_from_source(const LoadedScenario& loaded, const RunInputs& inputs,
                                 const std::filesystem::path& out, bool progress) {
  return source_for(loaded, inputs).run(loaded, inputs, out, progress);
}

ExperimentResult simulate_and_run(const LoadedScenario& loaded, const std::filesystem::path& out, bool progress) {
  return run_from_source(loaded, RunInputs{}, out, progress);
}

}  // namespace relslam::eval
