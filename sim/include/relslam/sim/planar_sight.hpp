#pragma once
// What the map-file reader checks along a planar path before a run: that the map's sensor sees
// two walls at once somewhere, and that the path does not run through a wall. Both cost time
// with the map, not with the path's length. Part of relslam/sim: Eigen only.

#include "relslam/sim/planar_map.hpp"
#include "relslam/sim/planar_path.hpp"

#include <optional>
#include <string>

namespace relslam::sim {

// The most work each check below may do, in tests of one wall against one pose or step (a
// noise-free sensor frame counts kSightFrameWork per wall it looks at): two seconds or so. A
// map whose path passes millions of iterations near walls it never sees runs out of it.
inline constexpr long long kMaxSightWork = 100'000'000;
inline constexpr long long kSightFrameWork = 16;

// The first iteration at which the map's sensor, without noise, reports at least `count`
// planes; none if the path never sees that many at once. A map whose path never sees two walls
// together gives the algorithm nothing to relate (Rule 7).
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
// Where the robot's path leaves its map: the first pose farther out than the sensor's reach
// from the box that holds every wall (from there nothing the map describes can be seen).
struct MapExit {
  int operation = 0;
  int iteration = 0;
  Eigen::Vector2d at = Eigen::Vector2d::Zero();
  Eigen::Vector2d low = Eigen::Vector2d::Zero(), high = Eigen::Vector2d::Zero();  // the walls' extent and reach
};
// The first pose of `path` outside that box, if any; none without a frustum (every wall always
// visible). Work: one pass over the path's poses (as building it), a MOVE by its two ends.
std::optional<MapExit> first_exit_from_map(const PlanarMap& map, const PlanarPath& path);
// The operation `index` of WallCrossing::operation in `program`, and where it stands: "steps[2]"
// or "then[0]", with the loop (1-based; 0 for `then`).
struct OperationPlace {
  const PathOperation* operation = nullptr;
  std::string field;
  int loop = 0;
};
OperationPlace operation_place(const PathProgram& program, int index);

}  // namespace relslam::sim
