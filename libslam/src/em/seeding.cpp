#include "relslam/em/seeding.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <utility>

namespace relslam::em {

std::optional<EmPlane> seed_plane(std::span<const Eigen::Vector3d> points, int start,
                                  std::span<const int> candidates, const EmOptions& options) {
  const Eigen::Vector3d& p = points[static_cast<std::size_t>(start)];
  // The two nearest by (squared distance, index).
  using Near = std::pair<double, int>;
  constexpr Near kNone{std::numeric_limits<double>::infinity(), -1};
  const double radius = std::max(options.seed_radius, options.seed_radius_per_range * p.norm());
  const double radius2 = radius * radius;
  // The nearest by (squared distance, index) among the candidates `usable` admits.
  auto nearest = [&](auto usable) {
    Near best = kNone;
    for (int i : candidates) {
      if (i == start) continue;
      const Near n{(points[static_cast<std::size_t>(i)] - p).squaredNorm(), i};
      if (n.first <= radius2 && n < best && usable(i)) best = n;
    }
    return best;
  };
  const Near first = nearest([](int) { return true; });
  if (first.second < 0) return std::nullopt;
  const Eigen::Vector3d a = points[static_cast<std::size_t>(first.second)] - p;
  const Near second = nearest([&](int i) {
    const Eigen::Vector3d b = points[static_cast<std::size_t>(i)] - p;
    const double scale = a.norm() * b.norm();
    return i != first.second && scale > 0.0 && a.cross(b).norm() >= options.min_seed_sine * scale;
  });
  if (second.second < 0) return std::nullopt;

  EmPlane plane;
  plane.points = {start, first.second, second.second};
  std::sort(plane.points.begin(), plane.points.end());
  plane.seed_point = start;
  if (!refit(plane, points)) return std::nullopt;
  return plane;
}

}  // namespace relslam::em
