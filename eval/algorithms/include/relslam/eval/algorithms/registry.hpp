#pragma once
// Every algorithm a scenario may list, by name: those of the point half (range-bearing frames)
// and those of the plane half (plane frames, scenario kind "planar"), in one registry whose
// entries say their half. Adding an algorithm is one entry in registry.cpp: its name, one line
// for `relslam algorithms`, its half and its factory.

#include "relslam/eval/algorithms/algorithm.hpp"
#include "relslam/eval/algorithms/plane_algorithm.hpp"
#include "relslam/eval/config/scenario_half.hpp"
#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/io/range_bearing.hpp"
#include "relslam/plane/field_of_view.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace relslam::eval {

// What a factory may read: the scenario's settings and the sensor the frames come from.
struct AlgorithmContext {
  const Scenario& scenario;
  const RangeBearingSensor& sensor;
};

// What a plane algorithm's factory may read: the scenario's settings and the map's anchor.
struct PlaneAlgorithmContext {
  const Scenario& scenario;
  PlanarPose world_T_start;  // the robot's first pose (Rule 4)
  // The sensor's field of view where the source knows it (PlaneFrameSource::field_of_view).
  std::optional<plane::FieldOfView> field_of_view = std::nullopt;
};

// One algorithm a scenario may list: its name, one line for `relslam algorithms`, the half whose
// frames it takes (scenario_half.hpp), and its factory for that half; the other factory is empty.
struct AlgorithmEntry {
  std::string name;  // as scenarios list it
  std::string help;  // one line: what it is, thesis section
  ScenarioHalf half;
  std::function<std::unique_ptr<Algorithm>(const AlgorithmContext&)> make;              // point half
  std::function<std::unique_ptr<PlaneAlgorithm>(const PlaneAlgorithmContext&)> make_plane;  // plane half
};

// Every algorithm of both halves, the point half's first: the one place an algorithm is found.
const std::vector<AlgorithmEntry>& algorithm_registry();
// Those of one half, in the registry's order.
std::vector<const AlgorithmEntry*> algorithms_of(ScenarioHalf half);
// Their names, ", "-separated, for messages.
std::string algorithm_names(ScenarioHalf half);
// nullptr when there is none of that name (in that half).
const AlgorithmEntry* find_algorithm(const std::string& name);
const AlgorithmEntry* find_algorithm(const std::string& name, ScenarioHalf half);

// Every name the scenario lists, and every value its sweeps and variants give "algorithms",
// must have an entry of the scenario's half (plane algorithms for kind "planar"): InputError
// at the offending key otherwise.
void check_algorithm_names(const LoadedScenario& loaded);
// The algorithm `name` (logic_error when unknown: scenarios are checked when loaded).
std::unique_ptr<Algorithm> make_algorithm(const std::string& name, const AlgorithmContext& context);
std::unique_ptr<PlaneAlgorithm> make_plane_algorithm(const std::string& name, const PlaneAlgorithmContext& context);

}  // namespace relslam::eval
