#include "relslam/eval/experiments/replay_manifest.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/tum_writer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

namespace relslam::eval {

namespace fs = std::filesystem;

namespace {

// The manifest sections of the sources that read their frames from files.
constexpr std::array<const char*, 4> kRecordedSources = {"rawlog", "victoria_park", "plane_file", "laser_rawlog"};

// The pose at iteration k in a TUM file (t = iteration), if it has one.
std::optional<Rigid3> recorded_pose(const fs::path& tum, int k) {
  if (!fs::exists(tum)) return std::nullopt;
  for (const TumPose& row : read_tum(tum))
    if (static_cast<int>(std::lround(row.time)) == k) return row.pose;
  return std::nullopt;
}

}  // namespace

ReplayManifest read_replay_manifest(const fs::path& run_dir) {
  const fs::path file = run_dir / "manifest.json";
  std::ifstream in(file);
  if (!in) throw InputError(file.string(), 0, "", "not found: render needs the folder of a relslam run");
  nlohmann::json manifest;
  try {
    manifest = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file.string(), 0, "", std::string("not a relslam manifest: ") + e.what());
  }
  // Runs whose frames were read from files (a rawlog, Victoria Park, a plane file, laser scans):
  // there is nothing to simulate again, and replaying the scenario would draw another run.
  const bool recorded = std::any_of(kRecordedSources.begin(), kRecordedSources.end(),
                                    [&](const char* source) { return manifest.contains(source); });
  if (!manifest.contains("scenario") || recorded)
    throw InputError(file.string(), 0, "", "render replays simulated runs (relslam run SCENARIO); this one is not: draw it from its files with --overview");
  LoadedScenario loaded = parse_scenario_with_overrides(manifest["scenario"].dump(), file.string(), {});
  return {run_dir, file, std::move(manifest), std::move(loaded)};
}

std::string compare_with_recorded(const fs::path& tum, int k, const Eigen::Vector3d& replayed) {
  const std::optional<Rigid3> recorded = recorded_pose(tum, k);
  if (!recorded) return "";  // the run stopped earlier or wrote no trajectory: nothing to compare
  // TUM rows carry about 9 significant digits.
  const double tolerance = 1e-6 * (1.0 + recorded->translation.norm());
  const double gap = (recorded->translation - replayed).norm();
  if (gap <= tolerance) return "";
  return "the replayed pose at iteration " + std::to_string(k) + " is " + std::to_string(gap) + " units from " +
         tum.string() + ": the run was made by another build or scenario, so the picture may not show it";
}

}  // namespace relslam::eval
