#include "relslam/eval/experiments/laser_experiment.hpp"

#include "relslam/eval/config/scenario_half.hpp"
#include "relslam/eval/experiments/require_algorithms.hpp"
#include "relslam/eval/experiments/run_skeleton.hpp"
#include "relslam/eval/sources/laser_plane_source.hpp"

namespace relslam::eval {

ExperimentResult run_on_laser_rawlog(const LoadedScenario& loaded, const std::string& rawlog, const std::string& field,
                                     const std::filesystem::path& out, bool progress) {
  if (!feeds_planes(loaded.scenario.kind))
    throw loaded.error("kind", "a 2-D laser log feeds the planar half: the scenario must be of kind \"planar\"");
  require_algorithms(loaded);
  LaserPlaneSource source(find_laser_rawlog(rawlog, field), loaded.scenario.laser.walls);
  PlanarExperiment experiment(loaded, source, out);
  return experiment.run(progress);
}

}  // namespace relslam::eval
