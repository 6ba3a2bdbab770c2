#include "relslam/eval/experiments/plane_replay.hpp"

#include "relslam/eval/algorithms/registry.hpp"
#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/config/scenario_half.hpp"
#include "relslam/eval/sources/planar_simulation_source.hpp"

#include <algorithm>

namespace relslam::eval {

namespace fs = std::filesystem;

namespace {

// The scenario with a map the simulator can read: by its name as when the run was made, else
// the file the run recorded having used (a run folder moved to another checkout, or a map
// given by a path relative to where relslam ran).
LoadedScenario with_map(LoadedScenario loaded, const nlohmann::json& manifest) {
  try {
    resolve_planar_map(loaded);
    return loaded;
  } catch (const InputError&) {
    const nlohmann::json* recorded = nullptr;
    if (manifest.contains("planar_simulation") && manifest["planar_simulation"].contains("map_file") &&
        manifest["planar_simulation"]["map_file"].is_string())
      recorded = &manifest["planar_simulation"]["map_file"];
    std::error_code ec;
    if (!recorded || !fs::is_regular_file(recorded->get<std::string>(), ec)) throw;
    loaded.scenario.planar.map = recorded->get<std::string>();
    return loaded;
  }
}

// The plane algorithm to replay: the one asked for, or the run's first.
std::string chosen_algorithm(const LoadedScenario& loaded, const fs::path& file, const std::string& requested) {
  const std::vector<std::string>& listed = loaded.scenario.algorithms;
  if (requested.empty()) {
    if (listed.empty()) throw InputError(file.string(), 0, "algorithms", "the run lists no algorithm");
    return listed.front();
  }
  if (!find_algorithm(requested, ScenarioHalf::Planes))
    throw InputError("", 0, "--algorithm",
                     "a planar run draws a plane algorithm (" + algorithm_names(ScenarioHalf::Planes) + "), not " +
                         requested);
  if (std::find(listed.begin(), listed.end(), requested) == listed.end())
    throw InputError(file.string(), 0, "--algorithm", "the run did not include " + requested);
  return requested;
}

// The sensor's footprint when walls are seen through it; scripted and always-visible maps
// (thesis 4.3.1-4.3.2, before the frustum existed) have none to draw.
std::optional<sim::ViewingFrustum> drawn_frustum(const sim::PlaneSensorOptions& sensor) {
  if (sensor.mode == sim::PlaneVisibility::Frustum || sensor.mode == sim::PlaneVisibility::FullSize)
    return sensor.frustum;
  return std::nullopt;
}

}  // namespace

struct PlaneReplay::State {
  LoadedScenario loaded;
  PlanarSimulationSource source;
  std::string name;
  std::unique_ptr<PlaneAlgorithm> algorithm;
  bool failed = false;  // it threw: its last good state is shown from then on, as the run recorded it
  PlaneFrame frame;     // the last one fed
  std::optional<PlanarPose> estimated_pose;  // the last valid one
  bool pose_now = false;                     // estimated at the last iteration fed
  PlanarPose true_pose;
  std::vector<Eigen::Vector2d> true_path, estimated_path;

  State(LoadedScenario scenario, std::string algorithm_name)
      : loaded(std::move(scenario)), source(loaded), name(std::move(algorithm_name)) {
    algorithm = make_plane_algorithm(name, {loaded.scenario, source.start()});
  }

  void feed(const sim::PlaneSimFrame& sim_frame) {
    frame = sim_frame.observation;
    true_pose = sim_frame.truth.world_T_robot;
    true_path.push_back(true_pose.translation);
    pose_now = false;
    if (failed) return;
    try {
      algorithm->step(frame);
    } catch (const std::exception&) {
      failed = true;
      return;
    }
    algorithm->read_out();
    if (const std::optional<PlanarPose> pose = algorithm->pose()) {
      estimated_pose = pose;
      pose_now = true;
      estimated_path.push_back(pose->translation);
    }
  }

  void describe_map(PlanarScene& scene) const {
    const std::vector<MappedPlane>& map = algorithm->map();
    for (const MappedPlane& m : map) scene.mapped.push_back(m.second);
    // map() is in ascending ids: a member is found by bisection.
    auto midpoint = [&](int id) -> std::optional<Eigen::Vector2d> {
      const auto it =
          std::lower_bound(map.begin(), map.end(), id, [](const MappedPlane& m, int v) { return m.first < v; });
      if (it == map.end() || it->first != id) return std::nullopt;
      return it->second.midpoint();
    };
    for (const PlaneGroup& g : algorithm->groups()) {
      PlanarSceneGroup drawn{g.id, g.world_pose.translation, {}};
      for (int id : g.planes)
        if (const auto m = midpoint(id)) drawn.member_midpoints.push_back(*m);
      scene.groups.push_back(std::move(drawn));
    }
  }
};

PlaneReplay::PlaneReplay(ReplayManifest manifest, const std::string& algorithm) {
  if (!feeds_planes(manifest.kind()))
    throw InputError(manifest.file.string(), 0, "", "not a planar run (kind \"planar\")");
  LoadedScenario loaded = with_map(std::move(manifest.loaded), manifest.json);
  std::string name = chosen_algorithm(loaded, manifest.file, algorithm);
  state_ = std::make_unique<State>(std::move(loaded), std::move(name));
}

PlaneReplay::PlaneReplay(PlaneReplay&&) noexcept = default;
PlaneReplay::~PlaneReplay() = default;

int PlaneReplay::iterations() const { return static_cast<int>(state_->source.frames()); }
const std::string& PlaneReplay::algorithm() const { return state_->name; }

void PlaneReplay::feed(int k) { state_->feed(state_->source.frame(k)); }

PlanarScene PlaneReplay::scene(int k) const {
  const State& s = *state_;
  PlanarScene scene = world_outline(-1);
  scene.true_path = s.true_path;
  scene.true_pose = s.true_pose;
  s.describe_map(scene);
  scene.estimated_pose = s.estimated_pose;
  scene.estimated_path = s.estimated_path;
  // The thesis's "current readings": this iteration's planes where the estimated pose puts them.
  if (s.estimated_pose)
    for (const PlaneObject& p : s.frame.planes) scene.readings.push_back(p.transformed(*s.estimated_pose));
  scene.title = s.loaded.scenario.name + "  " + s.name + "  iteration " + std::to_string(k) + "  seen " +
                std::to_string(s.frame.planes.size()) + "  mapped planes " + std::to_string(scene.mapped.size()) +
                "  groups " + std::to_string(scene.groups.size()) +
                (s.failed      ? "  (failed: its last good state)"
                 : !s.pose_now ? "  (no pose now: the last one drawn)"
                               : "");
  return scene;
}

PlanarScene PlaneReplay::world_outline(int last) const {
  const State& s = *state_;
  PlanarScene scene;
  // From the map, not source.walls(): that table is indexed by wall id and holds placeholders
  // where the map skips an id.
  for (const sim::Wall& w : s.source.map().world.walls) scene.walls.push_back({w.a, w.b, 0.0, w.height, 0});
  scene.frustum = drawn_frustum(s.source.simulator().sensor());
  for (int k = 0; k <= last && k < iterations(); ++k)
    scene.true_path.push_back(s.source.simulator().path().world_T_robot(k).translation);
  return scene;
}

std::optional<Eigen::Vector3d> PlaneReplay::position() const {
  const State& s = *state_;
  // The run wrote a trajectory row only where it had a pose (plane_recorder.cpp).
  if (!s.pose_now) return std::nullopt;
  return rigid_from_planar(*s.estimated_pose).translation;
}

}  // namespace relslam::eval
