#include "relslam/eval/algorithms/registry.hpp"

#include "ekf2d.hpp"
#include "ekf6d.hpp"
#include "relative_point.hpp"

#include <stdexcept>

namespace relslam::eval {

const std::vector<AlgorithmEntry>& algorithm_registry() {
  static const std::vector<AlgorithmEntry> entries = {
      {"relative_point", "Relative Point: relative maps of point groups, no odometry, no pose state (thesis 3, 6)",
       [](const AlgorithmContext& c) { return make_relative_point(c.scenario.relative_point); }},
      {"ekf6d", "MRPT's 6D range-bearing EKF-SLAM without odometry, the thesis's baseline (6.7)",
       [](const AlgorithmContext& c) { return make_ekf6d(c.scenario.ekf6d, c.sensor); }},
      {"ekf2d", "MRPT's planar EKF-SLAM with the vehicle's odometry, the Victoria Park reference (6.8)",
       [](const AlgorithmContext& c) { return make_ekf2d(c.scenario.ekf2d, true, c.sensor); }},
      {"ekf2d_no_odometry", "MRPT's planar EKF-SLAM without odometry (constant-position model)",
       [](const AlgorithmContext& c) { return make_ekf2d(c.scenario.ekf2d, false, c.sensor); }},
  };
  return entries;
}

const AlgorithmEntry* find_algorithm(const std::string& name) {
  for (const AlgorithmEntry& e : algorithm_registry())
    if (e.name == name) return &e;
  return nullptr;
}

namespace {

// "" or what is wrong with a list of names.
std::string unknown_name_problem(const std::vector<std::string>& names) {
  for (const std::string& name : names)
    if (!find_algorithm(name)) {
      std::string list;
      for (const AlgorithmEntry& e : algorithm_registry()) list += (list.empty() ? "" : ", ") + e.name;
      return "unknown algorithm \"" + name + "\" (known: " + list + ")";
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
  if (const std::string problem = unknown_name_problem(s.algorithms); !problem.empty())
    throw loaded.error("algorithms", problem);
  for (const SweepAxis& axis : s.sweep)
    if (axis.key == "algorithms")
      for (const nlohmann::json& value : axis.values)
        if (const std::string problem = unknown_name_problem(names_in(value)); !problem.empty())
          throw loaded.error("sweep.algorithms", problem);
  for (const Variant& variant : s.variants)
    for (const auto& [key, value] : variant.settings)
      if (key == "algorithms")
        if (const std::string problem = unknown_name_problem(names_in(value)); !problem.empty())
          throw loaded.error("variants." + variant.name + ".algorithms", problem);
}

std::unique_ptr<Algorithm> make_algorithm(const std::string& name, const AlgorithmContext& context) {
  const AlgorithmEntry* entry = find_algorithm(name);
  if (!entry) throw std::logic_error("make_algorithm: unknown algorithm " + name);
  return entry->make(context);
}

}  // namespace relslam::eval
