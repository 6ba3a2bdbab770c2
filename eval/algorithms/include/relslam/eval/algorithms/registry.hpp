#pragma once
// Every algorithm a scenario may list, by name: those of the point half (range-bearing frames)
// and those of the plane half (plane frames, scenario kind "planar"). Adding an algorithm is
// one entry in registry.cpp: its name, one line for `relslam algorithms`, and its factory.

#include "relslam/eval/algorithms/algorithm.hpp"
#include "relslam/eval/algorithms/plane_algorithm.hpp"
#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/io/range_bearing.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace relslam::eval {

// What a factory may read: the scenario's settings and the sensor the frames come from.
struct AlgorithmContext {
  const Scenario& scenario;
  const RangeBearingSensor& sensor;
};

struct AlgorithmEntry {
  std::string name;  // as scenarios list it
  std::string help;  // one line: what it is, thesis section
  std::function<std::unique_ptr<Algorithm>(const AlgorithmContext&)> make;
};

const std::vector<AlgorithmEntry>& algorithm_registry();
// nullptr when there is none of that name.
const AlgorithmEntry* find_algorithm(const std::string& name);

// What a plane algorithm's factory may read: the scenario's settings and the map's anchor.
struct PlaneAlgorithmContext {
  const Scenario& scenario;
  PlanarPose world_T_start;  // the robot's first pose (Rule 4)
};

struct PlaneAlgorithmEntry {
  std::string name;
  std::string help;
  std::function<std::unique_ptr<PlaneAlgorithm>(const PlaneAlgorithmContext&)> make;
};

const std::vector<PlaneAlgorithmEntry>& plane_algorithm_registry();
const PlaneAlgorithmEntry* find_plane_algorithm(const std::string& name);

// Every name the scenario lists, and every value its sweeps and variants give "algorithms",
// must have an entry of the scenario's half (plane algorithms for kind "planar"): InputError
// at the offending key otherwise.
void check_algorithm_names(const LoadedScenario& loaded);
// The algorithm `name` (logic_error when unknown: scenarios are checked when loaded).
std::unique_ptr<Algorithm> make_algorithm(const std::string& name, const AlgorithmContext& context);
std::unique_ptr<PlaneAlgorithm> make_plane_algorithm(const std::string& name, const PlaneAlgorithmContext& context);

}  // namespace relslam::eval
