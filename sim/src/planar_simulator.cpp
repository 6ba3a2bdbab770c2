#include "relslam/sim/planar_simulator.hpp"

#include "checked.hpp"

#include <stdexcept>

namespace relslam::sim {
PlanarSimulator::PlanarSimulator(const PlanarMap& map, std::uint64_t seed)
    : world_(checked(map.world)), path_(map.path), sensor_(map.sensor, seed) {}

PlanarSimulator::PlanarSimulator(const PlanarMap& map, std::uint64_t seed, const PointSensorOptions& points)
    : PlanarSimulator(map, seed) {
  point_sensor_.emplace(points, world_, seed);
}

PlaneSimFrame PlanarSimulator::frame(int k) const { return sensor_.observe(world_, path_.world_T_robot(k), k); }

const PointSensor& PlanarSimulator::point_sensor() const {
  if (!point_sensor_) throw std::logic_error("PlanarSimulator: built without a point sensor");
  return *point_sensor_;
}

PointSimFrame PlanarSimulator::point_frame(int k) const { return point_sensor().observe(path_.world_T_robot(k), k); }

}  // namespace relslam::sim
