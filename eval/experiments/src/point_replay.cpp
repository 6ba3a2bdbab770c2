#include "relslam/eval/experiments/point_replay.hpp"

#include "relslam/eval/algorithms/map_frame_gauge.hpp"
#include "relslam/eval/algorithms/registry.hpp"
#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/sources/simulated_world.hpp"
#include "relslam/point/rlt_mapper.hpp"
#include "relslam/relax/ceres_relaxation.hpp"

#include <algorithm>

namespace relslam::eval {

namespace fs = std::filesystem;

struct PointReplay::State {
  std::string algorithm;
  LoadedScenario loaded;
  sim::Simulator simulator;
  RangeBearingSensor sensor;
  std::optional<point::RltMapper> mapper;  // relative_point
  MapFrameGauge gauge;                     // its map frame in the world, as the run scored it
  std::unique_ptr<Algorithm> filter;       // ekf6d
  bool filter_failed = false;              // it threw: its last good state is shown from then on
  std::vector<Eigen::Vector3d> true_path, estimated_path;
  Rigid3 true_pose, estimated_pose;

  State(std::string name, LoadedScenario scenario)
      : algorithm(std::move(name)),
        loaded(std::move(scenario)),
        simulator(build_simulator(loaded)),
        sensor(sensor_of(loaded.scenario.sim)) {}

  void feed(const sim::SimFrame& frame) {
    if (mapper) {
      mapper->step(frame.observation);
      gauge.observe(frame.observation.iteration, mapper->first_iteration(), frame.truth);
      estimated_pose = gauge.pose(mapper->pose());
    } else if (!filter_failed) {
      try {
        filter->step(frame.observation, frame.truth);
        filter->read_out();
        estimated_pose = filter->pose();
      } catch (const std::exception&) {
        filter_failed = true;  // as the run recorded it: the filter's state before the failure
      }
    }
    true_pose = frame.truth.world_T_robot;
    true_path.push_back(true_pose.translation);
    estimated_path.push_back(estimated_pose.translation);
  }

  void describe_map(RenderScene& scene) const {
    if (!mapper) {
      for (int id : filter->map_ids()) scene.landmarks.push_back({*filter->position(id), id, -1, true, false});
      return;
    }
    std::vector<Eigen::Vector3d> sum(mapper->groups().size(), Eigen::Vector3d::Zero());
    std::vector<int> count(mapper->groups().size(), 0);
    for (const point::RltPoint& p : mapper->points()) {
      if (!p.has_global || p.merged) continue;
      const Eigen::Vector3d world = gauge.point(p.global);
      scene.landmarks.push_back({world, p.id, p.owner, p.final_grouped || p.level3_grouped, p.dynamic});
      if (p.owner >= 0 && !p.dynamic) {
        sum[p.owner] += world;
        ++count[p.owner];
      }
    }
    for (const point::RltGroup& g : mapper->groups())
      if (count[g.id()] > 0)
        scene.groups.push_back({g.id(), g.level() != point::GroupLevel::Temporary, sum[g.id()] / count[g.id()]});
  }
};

PointReplay::PointReplay(ReplayManifest manifest, const std::string& requested) {
  const std::string algorithm = requested.empty() ? "relative_point" : requested;
  const fs::path file = manifest.file;
  LoadedScenario loaded = std::move(manifest.loaded);
  if (loaded.scenario.kind != ScenarioKind::Simulation)
    throw InputError(file.string(), 0, "",
                     "not a point-world simulation (kind \"" + std::string(to_string(loaded.scenario.kind)) + "\")");
  const auto& listed = loaded.scenario.algorithms;
  if (algorithm != "relative_point" && algorithm != "ekf6d")
    throw InputError("", 0, "--algorithm", "render draws relative_point or ekf6d, not " + algorithm);
  if (std::find(listed.begin(), listed.end(), algorithm) == listed.end())
    throw InputError(file.string(), 0, "--algorithm", "the run did not include " + algorithm);
  state_ = std::make_unique<State>(algorithm, std::move(loaded));
  const Scenario& scenario = state_->loaded.scenario;
  if (algorithm == "relative_point") {
    state_->mapper.emplace(scenario.relative_point, relax::solve_relaxation);
  } else {
    state_->filter = make_algorithm(algorithm, {scenario, state_->sensor});
  }
}

PointReplay::PointReplay(PointReplay&&) noexcept = default;
PointReplay::~PointReplay() = default;

int PointReplay::iterations() const { return state_->simulator.iterations(); }

void PointReplay::feed(int k) { state_->feed(state_->simulator.frame(k)); }

RenderScene PointReplay::scene(int k) const {
  const State& s = *state_;
  RenderScene scene;
  const sim::World& world = s.simulator.world();
  for (int id = 0; id < world.size(); ++id) {
    scene.true_points.push_back(world.position(id, k));
    scene.true_dynamic.push_back(world.is_dynamic(id));
  }
  s.describe_map(scene);
  scene.true_pose = s.true_pose;
  scene.estimated_pose = s.estimated_pose;
  scene.true_path = s.true_path;
  scene.estimated_path = s.estimated_path;
  const sim::Frustum& f = s.loaded.scenario.sim.frustum;
  scene.frustum = {f.near, f.far, f.half_angle_rad};
  int final_groups = 0;
  for (const SceneGroup& g : scene.groups) final_groups += g.final;
  scene.title =
      s.loaded.scenario.name + "  " + s.algorithm + "  iteration " + std::to_string(k) + "  map points " +
      std::to_string(scene.landmarks.size()) +
      (s.mapper ? "  groups " + std::to_string(scene.groups.size()) + " (" + std::to_string(final_groups) + " final)"
                : "");
  return scene;
}

RenderScene PointReplay::world_outline(int last) const {
  RenderScene scene;
  scene.true_points = state_->simulator.world().anchors();
  for (int k = 0; k <= last && k < iterations(); ++k)
    scene.true_path.push_back(state_->simulator.path().world_T_robot(k).translation);
  return scene;
}

const std::string& PointReplay::algorithm() const { return state_->algorithm; }

std::optional<Eigen::Vector3d> PointReplay::position() const { return state_->estimated_pose.translation; }

}  // namespace relslam::eval
