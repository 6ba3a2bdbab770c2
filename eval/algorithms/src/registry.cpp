#include "relslam/eval/algorithms/registry.hpp"

#include "batch_optimum.hpp"
#include "ekf2d.hpp"
#include "ekf6d.hpp"
#include "icp_slam.hpp"
#include "relative_plane.hpp"
#include "relative_point.hpp"

#include <stdexcept>

namespace relslam::eval {

namespace {

AlgorithmEntry point_entry(std::string name, std::string help,
                           std::function<std::unique_ptr<Algorithm>(const AlgorithmContext&)> make) {
  return {std::move(name), std::move(help), ScenarioHalf::Points, std::move(make), {}};
}

AlgorithmEntry plane_entry(std::string name, std::string help,
                           std::function<std::unique_ptr<PlaneAlgorithm>(const PlaneAlgorithmContext&)> make) {
  return {std::move(name), std::move(help), ScenarioHalf::Planes, {}, std::move(make)};
}

// Relative Plane's options with the source's field of view. Relocalisation judges a place by it
// (plane/view_evidence.hpp): without one (laser logs, plane files) it would take places that fit
// the planes in view by chance, so it is off there.
plane::RelativePlaneOptions with_field_of_view(plane::RelativePlaneOptions options,
                                               const std::optional<plane::FieldOfView>& view) {
  if (view) options.integrity.field_of_view = *view;
  else options.integrity.recovery = false;
  return options;
}

}  // namespace

const std::vector<AlgorithmEntry>& algorithm_registry() {
  static const std::vector<AlgorithmEntry> entries = {
      point_entry("relative_point",
                  "Relative Point: relative maps of point groups, no odometry, no pose state (thesis 3, 6)",
                  [](const AlgorithmContext& c) { return make_relative_point(c.scenario.relative_point); }),
      point_entry("ekf6d",
                  "MRPT's 6D range-bearing EKF-SLAM, without odometry unless ekf6d.use_odometry: the thesis's "
                  "baseline (6.7)",
                  [](const AlgorithmContext& c) { return make_ekf6d(c.scenario.ekf6d, c.sensor); }),
      point_entry("ekf2d",
                  "MRPT's planar EKF-SLAM: with the vehicle's odometry, the Victoria Park reference (6.8); elsewhere "
                  "as ekf2d.use_odometry says",
                  [](const AlgorithmContext& c) {
                    const bool odometry =
                        c.scenario.kind == ScenarioKind::VictoriaPark || c.scenario.ekf2d.use_odometry;
                    return make_ekf2d(c.scenario.ekf2d, "ekf2d", odometry, c.sensor);
                  }),
      point_entry("ekf2d_no_odometry", "MRPT's planar EKF-SLAM without odometry (constant-position model)",
                  [](const AlgorithmContext& c) {
                    return make_ekf2d(c.scenario.ekf2d, "ekf2d_no_odometry", false, c.sensor);
                  }),
      point_entry("batch_optimum",
                  "The accuracy floor (beyond the thesis): nonlinear least squares over every pose and landmark "
                  "with the sensor's noise model and known ids, solved once after the last frame",
                  [](const AlgorithmContext& c) {
                    return make_batch_optimum(c.scenario.batch_optimum, c.scenario.ekf6d, c.scenario.relative_point,
                                              c.sensor, c.scenario.seed);
                  }),
      plane_entry("relative_plane",
                  "Relative Plane: relative maps of wall groups, no odometry, pose from scratch each frame (thesis 4)",
                  [](const PlaneAlgorithmContext& c) {
                    return make_relative_plane(with_field_of_view(c.scenario.relative_plane, c.field_of_view),
                                               c.scenario.motion_prediction, c.world_T_start);
                  }),
      plane_entry("icp_slam",
                  "MRPT's ICP-SLAM (CMetricMapBuilderICP) on laser scans, options icp_slam.* as its "
                  "icp-slam_demo_classic.ini: the scan-matching baseline; no planes",
                  [](const PlaneAlgorithmContext& c) { return make_icp_slam(c.scenario.icp_slam, c.world_T_start); }),
      plane_entry("odometry", "dead reckoning: the start pose followed by every frame's odometry; no planes",
                  [](const PlaneAlgorithmContext& c) { return make_odometry(c.world_T_start); }),
      plane_entry("wall_odometry",
                  "Relative Plane's motion prediction alone: each frame's walls registered against the previous "
                  "frame's (motion_prediction.*); no planes",
                  [](const PlaneAlgorithmContext& c) {
                    return make_wall_odometry(c.scenario.motion_prediction, c.world_T_start);
                  }),
  };
  return entries;
}

std::vector<const AlgorithmEntry*> algorithms_of(ScenarioHalf half) {
  std::vector<const AlgorithmEntry*> of_half;
  for (const AlgorithmEntry& e : algorithm_registry())
    if (e.half == half) of_half.push_back(&e);
  return of_half;
}

std::string algorithm_names(ScenarioHalf half) {
  std::string list;
  for (const AlgorithmEntry* e : algorithms_of(half)) list += (list.empty() ? "" : ", ") + e->name;
  return list;
}

const AlgorithmEntry* find_algorithm(const std::string& name) {
  for (const AlgorithmEntry& e : algorithm_registry())
    if (e.name == name) return &e;
  return nullptr;
}

const AlgorithmEntry* find_algorithm(const std::string& name, ScenarioHalf half) {
  const AlgorithmEntry* entry = find_algorithm(name);
  return entry && entry->half == half ? entry : nullptr;
}

namespace {

// "" or what is wrong with a list of names, for a scenario feeding this half.
std::string unknown_name_problem(const std::vector<std::string>& names, ScenarioHalf half) {
  const bool planar = half == ScenarioHalf::Planes;
  for (const std::string& name : names) {
    const AlgorithmEntry* entry = find_algorithm(name);
    if (entry && entry->half == half) continue;
    const std::string known = algorithm_names(half);
    if (entry)
      return "\"" + name + "\" runs on " + (planar ? "point landmarks" : "planes (kind \"planar\")") +
             ", not on this scenario's " + (planar ? "planes" : "point landmarks") + " (here: " + known + ")";
    return "unknown algorithm \"" + name + "\" (known: " + known + ")";
  }
  return "";
}

std::vector<std::string> names_in(const nlohmann::json& value) {
  std::vector<std::string> names;
  for (const nlohmann::json& item : value)
    if (item.is_string()) names.push_back(item.get<std::string>());
  return names;
}

}  // namespace

void check_algorithm_names(const LoadedScenario& loaded) {
  const Scenario& s = loaded.scenario;
  const ScenarioHalf half = half_of(s.kind);
  if (const std::string problem = unknown_name_problem(s.algorithms, half); !problem.empty())
    throw loaded.error("algorithms", problem);
  for (const SweepAxis& axis : s.sweep)
    if (axis.key == "algorithms")
      for (const nlohmann::json& value : axis.values)
        if (const std::string problem = unknown_name_problem(names_in(value), half); !problem.empty())
          throw loaded.error("sweep.algorithms", problem);
  for (const Variant& variant : s.variants)
    for (const auto& [key, value] : variant.settings)
      if (key == "algorithms")
        if (const std::string problem = unknown_name_problem(names_in(value), half); !problem.empty())
          throw loaded.error("variants." + variant.name + ".algorithms", problem);
}

std::unique_ptr<Algorithm> make_algorithm(const std::string& name, const AlgorithmContext& context) {
  const AlgorithmEntry* entry = find_algorithm(name, ScenarioHalf::Points);
  if (!entry) throw std::logic_error("make_algorithm: unknown algorithm " + name);
  return entry->make(context);
}

std::unique_ptr<PlaneAlgorithm> make_plane_algorithm(const std::string& name, const PlaneAlgorithmContext& context) {
  const AlgorithmEntry* entry = find_algorithm(name, ScenarioHalf::Planes);
  if (!entry) throw std::logic_error("make_plane_algorithm: unknown plane algorithm " + name);
  return entry->make_plane(context);
}

}  // namespace relslam::eval
