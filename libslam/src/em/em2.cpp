#include "relslam/em/em2.hpp"

#include "options_check.hpp"
#include "relslam/em/culling.hpp"
#include "relslam/em/density_check.hpp"
#include "relslam/em/em_random.hpp"
#include "relslam/em/merging.hpp"
#include "relslam/em/seeding.hpp"
#include "relslam/em/tight_refit.hpp"
#include "relslam/spatial/ovlp_quadtree.hpp"

#include <algorithm>
#include <cmath>

namespace relslam::em {
namespace {

// Grows a seeded plane inside its cell (thesis 3.5.3 step 5); false when it ends up unusable.
bool grow(EmPlane& plane, std::span<const Eigen::Vector3d> points, std::span<const spatial::IndexedPoint> cell,
          const EmOptions& o) {
  for (int round = 0; round < o.em2.grow_rounds; ++round) {
    std::vector<int> gathered;
    for (const spatial::IndexedPoint& e : cell)
      if (plane.accepts(e.p, o)) gathered.push_back(e.id);
    std::sort(gathered.begin(), gathered.end());
    EmPlane next = plane;
    next.points = std::move(gathered);
    if (!refit(next, points)) return false;
    next.points = density_check(points, next, o);
    if (!refit(next, points)) return false;
    const bool settled = next.points == plane.points;
    plane = std::move(next);
    if (settled) break;
  }
  return static_cast<int>(plane.points.size()) >= o.min_support;
}

}  // namespace

EmResult run_em2(std::span<const Eigen::Vector3d> points, const EmOptions& o, std::uint64_t seed) {
  require_valid(o);
  EmResult result;
  const std::vector<int> finite = finite_points(points);
  result.ignored_points = static_cast<int>(points.size() - finite.size());
  if (finite.size() < 3) return result;
  EmRandom random(seed);
  std::vector<EmPlane>& planes = result.planes;

  std::vector<spatial::IndexedPoint> indexed;
  indexed.reserve(finite.size());
  for (int i : finite) indexed.push_back({i, points[static_cast<std::size_t>(i)]});
  spatial::OVLPQuadTree grid(o.em2.grid_cell, o.em2.grid_overlap);
  grid.build(indexed);

  const double left =
      std::max(static_cast<double>(o.em2.left_min), o.em2.left_fraction * static_cast<double>(finite.size()));
  std::vector<int> usage(points.size(), 0);
  std::vector<int> unassigned, neighbours;
  int failures = 0;
  while (result.iterations < o.em2.max_iterations) {
    unassigned.clear();
    for (int i : finite)
      if (usage[static_cast<std::size_t>(i)] == 0) unassigned.push_back(i);
    if (static_cast<double>(unassigned.size()) <= left || unassigned.size() < 3) break;
    ++result.iterations;

    const int start = unassigned[random.below(unassigned.size())];
    const std::span<const spatial::IndexedPoint> cell = grid.query(points[static_cast<std::size_t>(start)]);
    neighbours.clear();
    for (const spatial::IndexedPoint& e : cell)
      if (usage[static_cast<std::size_t>(e.id)] == 0) neighbours.push_back(e.id);
    std::optional<EmPlane> plane = seed_plane(points, start, neighbours, o);
    if (!plane || !grow(*plane, points, cell, o)) {
      if (++failures >= o.seed_attempts) break;
      continue;
    }
    failures = 0;
    plane->age = 1;
    plane->established = true;
    planes.push_back(std::move(*plane));
    merge_planes(planes, points, o);
    usage = usage_counts(planes, points.size());
  }

  absorb_unassigned(planes, points, finite, o, o.em2.absorb_passes);
  cull_exclusivity(planes, points.size(), o, 0);
  tight_refit(planes, points, o);
  set_rectangles(planes, points, o);
  return result;
}

}  // namespace relslam::em
