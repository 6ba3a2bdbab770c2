#pragma once
// Distances of a point from a wall, for the tests that check extracted walls (laser, depth)
// against their true walls in the planar world's (x, z) floor plane.

#include "relslam/core/plane_object.hpp"

#include <Eigen/Core>

#include <cmath>

namespace relslam::test {

// Distance of p from the infinite line through `wall`.
inline double line_distance(const Eigen::Vector2d& p, const PlaneObject& wall) {
  const Eigen::Vector2d u = (wall.b - wall.a).normalized(), d = p - wall.a;
  return std::abs(u.x() * d.y() - u.y() * d.x());
}

}  // namespace relslam::test
