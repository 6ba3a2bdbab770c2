#include "relslam/sim/planar_simulator.hpp"

#include "checked.hpp"

namespace relslam::sim {
PlanarSimulator::PlanarSimulator(const PlanarMap& map, std::uint64_t seed)
    : world_(checked(map.world)), path_(map.path), sensor_(map.sensor, seed) {}

PlaneSimFrame PlanarSimulator::frame(int k) const { return sensor_.observe(world_, path_.world_T_robot(k), k); }

std::optional<int> first_iteration_seeing(const PlanarMap& map, int count) {
  PlanarMap exact = map;
  exact.sensor.noise = PlaneNoiseOptions::none();
  const PlanarSimulator simulator(exact, 0);
  for (int k = 0; k < simulator.iterations(); ++k)
    if (static_cast<int>(simulator.frame(k).observation.planes.size()) >= count) return k;
  return std::nullopt;
}

}  // namespace relslam::sim
