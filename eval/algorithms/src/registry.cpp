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

template <class Entry>
const Entry* find_in(const std::vector<Entry>& entries, const std::string& name) {
  for (const Entry& e : entries)
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace

const std::vector<AlgorithmEntry>& algorithm_registry() {
  static const std::vector<AlgorithmEntry> entries = {
      {"relative_point", "Relative Point: relative maps of point groups, no odometry, no pose state (thesis 3, 6)",
       [](const AlgorithmContext& c) { return make_relative_point(c.scenario.relative_point); }},
      {"ekf6d",
       "MRPT's 6D range-bearing EKF-SLAM, without odometry unless ekf6d.use_odometry: the thesis's baseline (6.7)",
       [](const AlgorithmContext& c) { return make_ekf6d(c.scenario.ekf6d, c.sensor); }},
      {"ekf2d",
       "MRPT's planar EKF-SLAM: with the vehicle's odometry, the Victoria Park reference (6.8); elsewhere as "
       "ekf2d.use_odometry says",
       [](const AlgorithmContext& c) {
         const bool odometry = c.scenario.kind == ScenarioKind::VictoriaPark || c.scenario.ekf2d.use_odometry;
         return make_ekf2d(c.scenario.ekf2d, "ekf2d", odometry, c.sensor);
       }},
      {"ekf2d_no_odometry", "MRPT's planar EKF-SLAM without odometry (constant-position model)",
       [](const AlgorithmContext& c) { return make_ekf2d(c.scenario.ekf2d, "ekf2d_no_odometry", false, c.sensor); }},
      {"batch_optimum",
       "The accuracy floor (beyond the thesis): nonlinear least squares over every pose and landmark with the sensor's "
       "noise model and known ids, solved once after the last frame",
       [](const AlgorithmContext& c) {
         return make_batch_optimum(c.scenario.batch_optimum, c.scenario.relative_point, c.sensor, c.scenario.seed);
       }},
  };
  return entries;
}

const std::vector<PlaneAlgorithmEntry>& plane_algorithm_registry() {
  static const std::vector<PlaneAlgorithmEntry> entries = {
      {"relative_plane",
       "Relative Plane: relative maps of wall groups, no odometry, pose from scratch each frame (thesis 4)",
       [](const PlaneAlgorithmContext& c) {
         return make_relative_plane(c.scenario.relative_plane, c.scenario.motion_prediction, c.world_T_start);
       }},
      {"icp_slam",
       "MRPT's ICP-SLAM (CMetricMapBuilderICP) on laser scans, options icp_slam.* as its icp-slam_demo_classic.ini: "
       "the scan-matching baseline; no planes",
       [](const PlaneAlgorithmContext& c) { return make_icp_slam(c.scenario.icp_slam, c.world_T_start); }},
      {"odometry", "dead reckoning: the start pose followed by every frame's odometry; no planes",
       [](const PlaneAlgorithmContext& c) { return make_odometry(c.world_T_start); }},
  };
  return entries;
}

const AlgorithmEntry* find_algorithm(const std::string& name) { return find_in(algorithm_registry(), name); }
const PlaneAlgorithmEntry* find_plane_algorithm(const std::string& name) {
  return find_in(plane_algorithm_registry(), name);
}

namespace {

template <class Entry>
std::string names_of(const std::vector<Entry>& entries) {
  std::string list;
  for (const Entry& e : entries) list += (list.empty() ? "" : ", ") + e.name;
  return list;
}

// "" or what is wrong with a list of names, for a scenario of this kind.
std::string unknown_name_problem(const std::vector<std::string>& names, ScenarioKind kind) {
  const bool planar = kind == ScenarioKind::Planar;
  for (const std::string& name : names) {
    if (planar ? find_plane_algorithm(name) != nullptr : find_algorithm(name) != nullptr) continue;
    const bool other_half = planar ? find_algorithm(name) != nullptr : find_plane_algorithm(name) != nullptr;
    const std::string known = planar ? names_of(plane_algorithm_registry()) : names_of(algorithm_registry());
    if (other_half)
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
  if (const std::string problem = unknown_name_problem(s.algorithms, s.kind); !problem.empty())
    throw loaded.error("algorithms", problem);
  for (const SweepAxis& axis : s.sweep)
    if (axis.key == "algorithms")
      for (const nlohmann::json& value : axis.values)
        if (const std::string problem = unknown_name_problem(names_in(value), s.kind); !problem.empty())
          throw loaded.error("sweep.algorithms", problem);
  for (const Variant& variant : s.variants)
    for (const auto& [key, value] : variant.settings)
      if (key == "algorithms")
        if (const std::string problem = unknown_name_problem(names_in(value), s.kind); !problem.empty())
          throw loaded.error("variants." + variant.name + ".algorithms", problem);
}

std::unique_ptr<Algorithm> make_algorithm(const std::string& name, const AlgorithmContext& context) {
  const AlgorithmEntry* entry = find_algorithm(name);
  if (!entry) throw std::logic_error("make_algorithm: unknown algorithm " + name);
  return entry->make(context);
}

std::unique_ptr<PlaneAlgorithm> make_plane_algorithm(const std::string& name, const PlaneAlgorithmContext& context) {
  const PlaneAlgorithmEntry* entry = find_plane_algorithm(name);
  if (!entry) throw std::logic_error("make_plane_algorithm: unknown plane algorithm " + name);
  return entry->make(context);
}

}  // namespace relslam::eval
