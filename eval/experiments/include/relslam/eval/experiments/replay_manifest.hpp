#pragma once
// What every replay of a run folder starts from (replay.hpp, for either half): the manifest.json
// of relslam run, whose resolved scenario and seed make the run deterministic, and the recorded
// trajectory a replay checks itself by.

#include "relslam/core/rigid.hpp"
#include "relslam/eval/config/scenario_loading.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace relslam::eval {

struct ReplayManifest {
  std::filesystem::path run_dir;
  std::filesystem::path file;  // run_dir/manifest.json
  nlohmann::json json;         // the whole manifest
  LoadedScenario loaded;       // its "scenario", as loaded from a file

  ScenarioKind kind() const { return loaded.scenario.kind; }
};

// Throws InputError when `run_dir` has no manifest.json, or one not of a simulated run (relslam
// run or simulate on a scenario; rawlog and Victoria Park runs cannot be replayed).
ReplayManifest read_replay_manifest(const std::filesystem::path& run_dir);

// Empty when `replayed` is the pose the run recorded at iteration k in `tum` (or it recorded
// none), else the message: the binary or the scenario changed since the run.
std::string compare_with_recorded(const std::filesystem::path& tum, int k, const Eigen::Vector3d& replayed);

}  // namespace relslam::eval
