#include "relslam/eval/scenario_loading.hpp"

namespace relslam::eval {

LoadedScenario load_with_overrides(const std::string& file, const std::vector<std::string>& set) {
  std::vector<Override> overrides;
  for (const std::string& text : set) overrides.push_back(parse_override(text));
  return load_scenario(file, overrides);
}

sim::Simulator build_simulator(const LoadedScenario& loaded) {
  if (loaded.scenario.kind != ScenarioKind::Simulation)
    throw loaded.error("kind", "this scenario is not a simulation; it is run by its own command");
  try {
    return sim::Simulator(loaded.scenario.sim, loaded.scenario.seed);
  } catch (const OptionError& e) {
    throw loaded.error("sim." + e.field(), e.problem());
  }
}

LandmarkTruth landmark_truth(const sim::World& world) {
  LandmarkTruth truth;
  truth.positions = world.anchors();
  truth.dynamic_ids = world.dynamic_ids();
  truth.dynamic_position = [&world](int id, int k) { return world.position(id, k); };
  return truth;
}

}  // namespace relslam::eval
