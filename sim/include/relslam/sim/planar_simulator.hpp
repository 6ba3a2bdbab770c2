#pragma once
// The seeded planar-world simulator of thesis Chapters 4 and 5 (thesis 4.4.2): a
// robot on its path, reporting the walls it sees as planes (Chapter 4) or as points on them
// (Chapter 5). Part of relslam/sim.

#include "relslam/sim/planar_map.hpp"
#include "relslam/sim/planar_path.hpp"
#include "relslam/sim/planar_world.hpp"
#include "relslam/sim/plane_sensor.hpp"
#include "relslam/sim/point_sensor.hpp"

#include <cstdint>
#include <optional>

namespace relslam::sim {

// Builds the path once; frame(k) is then a pure function of (map, seed, k), like Simulator:
// frames can be made in any order and from several threads, and the same seed gives the same
// bits.
class PlanarSimulator {
 public:
  // Throws OptionError when the world, the path or the sensor fails its check().
  PlanarSimulator(const PlanarMap& map, std::uint64_t seed);
  // ... with the point sensor too (its static field is built here, from the same seed), so
  // point_frame() can be asked for. Throws OptionError when `points` fails its check().
  PlanarSimulator(const PlanarMap& map, std::uint64_t seed, const PointSensorOptions& points);

  int iterations() const { return path_.iterations(); }
  const PlanarWorld& world() const { return world_; }
  const PlanarPath& path() const { return path_; }
  const PlaneSensorOptions& sensor() const { return sensor_.options(); }

  // The true pose at k (thesis 4.4.2) and what the sensor reports there (thesis 4.4.2).
  PlaneSimFrame frame(int k) const;

  bool has_point_sensor() const { return point_sensor_.has_value(); }
  const PointSensor& point_sensor() const;  // throws std::logic_error without one
  // What the point sensor reports at k (thesis 5.1); pure in (map, options, seed, k) like
  // frame(k). Throws std::logic_error when the simulator was built without a point sensor.
  PointSimFrame point_frame(int k) const;

 private:
  PlanarWorld world_;
  PlanarPath path_;
  PlaneSensor sensor_;
  std::optional<PointSensor> point_sensor_;
};

}  // namespace relslam::sim
