#include "relslam/eval/sources/simulated_world.hpp"

namespace relslam::eval {

sim::Simulator build_simulator(const LoadedScenario& loaded) {
  if (loaded.scenario.kind != ScenarioKind::Simulation)
    throw loaded.error("kind", "this scenario is not a simulation; it is run by its own command");
  try {
    return sim::Simulator(loaded.scenario.sim, loaded.scenario.seed);
  } catch (const OptionError& e) {
    throw loaded.error("sim." + e.field(), e.problem());
  }
}

RangeBearingSensor sensor_of(const sim::SimOptions& o) {
  RangeBearingSensor s;
  s.min_range = o.frustum.near;
  s.max_range = o.frustum.max_range();
  s.field_of_view_yaw_rad = 2.0 * o.frustum.half_angle_rad;
  s.field_of_view_pitch_rad = o.frustum.vertical_field_of_view_rad();
  s.std_range = o.noise_sigma;
  return s;
}

LandmarkTruth landmark_truth(const sim::World& world) {
  LandmarkTruth truth;
  truth.positions = world.anchors();
  truth.dynamic_ids = world.dynamic_ids();
  return truth;
}

}  // namespace relslam::eval
