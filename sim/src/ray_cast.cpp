#include "relslam/sim/ray_cast.hpp"

#include <algorithm>
#include <cmath>

namespace relslam::sim {
namespace {

double cross(const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); }

// Distance along the ray to wall a→b, or nothing. Solves origin + s·d = a + t·(b − a) by
// Cramer's rule; the ends of the wall (t = 0, 1) count as hits.
std::optional<double> hit_distance(const Eigen::Vector2d& origin, const Eigen::Vector2d& d, const Wall& wall) {
  const Eigen::Vector2d e = wall.b - wall.a;
  const double denominator = cross(d, e);
  if (denominator == 0.0) return std::nullopt;  // parallel, or along the wall's line
  const Eigen::Vector2d w = wall.a - origin;
  const double s = cross(w, e) / denominator;
  const double t = cross(w, d) / denominator;
  if (!(s > 0.0) || t < 0.0 || t > 1.0) return std::nullopt;
  return s;
}

}  // namespace

std::vector<RayHit> ray_hits(const PlanarWorld& world, const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
                             double max_distance) {
  std::vector<RayHit> hits;
  for (std::size_t i = 0; i < world.walls.size(); ++i)
    if (const std::optional<double> s = hit_distance(origin, direction, world.walls[i]); s && *s <= max_distance)
      hits.push_back({*s, static_cast<int>(i)});
  std::sort(hits.begin(), hits.end(), [](const RayHit& l, const RayHit& r) {
    return l.distance != r.distance ? l.distance < r.distance : l.wall < r.wall;
  });
  return hits;
}

std::optional<RayHit> first_ray_hit(const PlanarWorld& world, const Eigen::Vector2d& origin,
                                    const Eigen::Vector2d& direction, double max_distance) {
  std::optional<RayHit> best;
  for (std::size_t i = 0; i < world.walls.size(); ++i) {
    const std::optional<double> s = hit_distance(origin, direction, world.walls[i]);
    if (s && *s <= max_distance && (!best || *s < best->distance)) best = RayHit{*s, static_cast<int>(i)};
  }
  return best;
}

}  // namespace relslam::sim
