#pragma once
// A planar experiment on a recorded 2-D laser log: the walls of every scan (laser_plane_source.hpp)
// through the scenario's plane algorithms into one run folder. Poses are not scored (no ground
// truth); pose validity, planes on the map and timings are.

#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/experiment_result.hpp"

#include <filesystem>
#include <string>

namespace relslam::eval {

// Runs the planar scenario `loaded` on the laser log `rawlog` (a path, or a file name in MRPT's
// installed data sets); `field` names where the log was given, for messages.
ExperimentResult run_on_laser_rawlog(const LoadedScenario& loaded, const std::string& rawlog, const std::string& field,
                                     const std::filesystem::path& out, bool progress);

}  // namespace relslam::eval
