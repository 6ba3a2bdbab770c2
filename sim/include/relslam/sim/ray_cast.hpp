#pragma once
// Ray casting the planar world: where a horizontal ray from the robot meets the walls. The one
// geometric core of the range sensors (the 2-D laser, laser_sensor.hpp, and the depth camera,
// depth_camera.hpp): walls are infinitely thin vertical segments spanning floor to their height
// (thesis 4.4.2.4's world), so a ray's hits in the floor plan are its hits in space, and a
// sensor above the floor only has to ask which of them lies within a wall's height. Part of
// relslam/sim: Eigen only.

#include "relslam/sim/planar_world.hpp"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace relslam::sim {

// One wall crossed by a ray: its distance along the ray (the ray's direction is a unit vector,
// so this is in map units) and its position in PlanarWorld::walls.
struct RayHit {
  double distance = 0;
  int wall = -1;
};

// Every wall the ray origin + s·direction (direction of unit length, world (x, z)) meets for
// 0 < s <= max_distance, nearest first (ties by wall position). A laser sees a wall from both
// sides, whatever its back-face flag: that flag is the thesis's plane sensor's, a wall is
// physical. A ray along a wall's line does not hit it (an infinitely thin wall seen edge-on).
std::vector<RayHit> ray_hits(const PlanarWorld& world, const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
                             double max_distance);

// The nearest of ray_hits(), if any.
std::optional<RayHit> first_ray_hit(const PlanarWorld& world, const Eigen::Vector2d& origin,
                                    const Eigen::Vector2d& direction, double max_distance);

}  // namespace relslam::sim
