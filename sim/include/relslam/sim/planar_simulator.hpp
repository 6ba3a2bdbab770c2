#pragma once
// The seeded planar-world simulator of thesis Chapters 4 and 5 (relative_plane_em.md §3): a
// robot on its path, reporting the walls it sees as planes (Chapter 4) or as points on them
// (Chapter 5). Part of relslam/sim.

#include "relslam/sim/planar_map.hpp"
#include "relslam/sim/planar_path.hpp"
#include "relslam/sim/planar_world.hpp"
#include "relslam/sim/plane_sensor.hpp"
#include "relslam/sim/point_sensor.hpp"

#include <cstdint>
#include <optional>
#include <string>

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

  // The true pose at k (spec §3.2) and what the sensor reports there (spec §3.4).
  PlaneSimFrame frame(int k) const;

  bool has_point_sensor() const { return point_sensor_.has_value(); }
  const PointSensor& point_sensor() const;  // throws std::logic_error without one
  // What the point sensor reports at k (spec §3.5); pure in (map, options, seed, k) like
  // frame(k). Throws std::logic_error when the simulator was built without a point sensor.
  PointSimFrame point_frame(int k) const;

 private:
  PlanarWorld world_;
  PlanarPath path_;
  PlaneSensor sensor_;
  std::optional<PointSensor> point_sensor_;
};

// The most work each check below may do, in tests of one wall against one pose or step (a
// noise-free sensor frame counts kSightFrameWork per wall it looks at): two seconds or so. A
// map whose path passes millions of iterations near walls it never sees runs out of it.
inline constexpr long long kMaxSightWork = 100'000'000;
inline constexpr long long kSightFrameWork = 16;

// The first iteration at which the map's sensor, without noise, reports at least `count`
// planes; none if the path never sees that many at once. A map whose path never sees two walls
// together gives the algorithm nothing to relate (Rule 7; spec A26).
//
// Cost grows with the map, not the path: walls out of the sensor's reach of an operation's
// bounding box are set aside for the whole operation, and a sensor frame is made only where
// `count` walls are within reach and face the robot. Throws OptionError (field "path") when the
// answer needs more than kMaxSightWork, or when the map fails its checks.
std::optional<int> first_iteration_seeing(const PlanarMap& map, int count);
// The same on `path`, built from map.path.
std::optional<int> first_iteration_seeing(const PlanarMap& map, const PlanarPath& path, int count);

// Where the robot's path runs through a wall: the operation in the order run (loops unrolled,
// then `then`), the wall's position in the map, and the iterations either side of the crossing.
struct WallCrossing {
  int operation = 0;
  int wall = 0;
  int before = 0;  // the last iteration on the side the robot came from
  Eigen::Vector2d at = Eigen::Vector2d::Zero();
};
// The first crossing of a wall by the segments between consecutive poses; a path that only
// touches a wall or runs along it does not cross it. Work: a MOVE is one segment whatever its
// length; the steps of an ARC are tested against the walls its bounding box meets.
// `path` is built from map.path.
std::optional<WallCrossing> first_wall_crossing(const PlanarMap& map, const PlanarPath& path);
// The operation `index` of WallCrossing::operation in `program`, and where it stands: "steps[2]"
// or "then[0]", with the loop (1-based; 0 for `then`).
struct OperationPlace {
  const PathOperation* operation = nullptr;
  std::string field;
  int loop = 0;
};
OperationPlace operation_place(const PathProgram& program, int index);

}  // namespace relslam::sim
