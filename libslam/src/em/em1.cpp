#include "relslam/em/em1.hpp"

#include "options_check.hpp"
#include "relslam/em/culling.hpp"
#include "relslam/em/em_random.hpp"
#include "relslam/em/merging.hpp"
#include "relslam/em/seeding.hpp"
#include "relslam/em/tight_refit.hpp"

#include <cmath>
#include <limits>

namespace relslam::em {
namespace {

// E-step: every point against every plane; returns the usage counters and fills `unassigned`.
std::vector<int> assign(std::vector<EmPlane>& planes, std::span<const Eigen::Vector3d> points,
                        const std::vector<int>& finite, const EmOptions& o, std::vector<int>& unassigned) {
  for (EmPlane& plane : planes) plane.points.clear();
  std::vector<int> usage(points.size(), 0);
  unassigned.clear();
  // The tests read the boxes of the previous M-step, so they are kept aside while lists refill.
  for (int i : finite) {
    const Eigen::Vector3d& p = points[static_cast<std::size_t>(i)];
    if (o.assign_mode == AssignMode::All) {
      for (EmPlane& plane : planes)
        if (plane.accepts(p, o)) {
          plane.points.push_back(i);
          ++usage[static_cast<std::size_t>(i)];
        }
    } else {
      EmPlane* nearest = nullptr;
      double best = std::numeric_limits<double>::infinity();
      for (EmPlane& plane : planes)
        if (plane.accepts(p, o) && std::abs(plane.distance(p)) < best) {
          best = std::abs(plane.distance(p));
          nearest = &plane;
        }
      if (nearest) {
        nearest->points.push_back(i);
        usage[static_cast<std::size_t>(i)] = 1;
      }
    }
    if (usage[static_cast<std::size_t>(i)] == 0) unassigned.push_back(i);
  }
  for (EmPlane& plane : planes) {
    update_box(plane, points);
    ++plane.age;
  }
  return usage;
}

}  // namespace

EmResult run_em1(std::span<const Eigen::Vector3d> points, const EmOptions& o, std::uint64_t seed) {
  require_valid(o);
  EmResult result;
  const std::vector<int> finite = finite_points(points);
  result.ignored_points = static_cast<int>(points.size() - finite.size());
  if (finite.size() < 3) return result;
  EmRandom random(seed);
  std::vector<EmPlane>& planes = result.planes;
  std::vector<int> unassigned;
  std::vector<char> taken(points.size(), 0);
  // Seeds made in iteration 1 can first be established at iteration 1 + cull_age: patience
  // runs from there.
  int last_progress = 1 + o.em1.cull_age;
  std::size_t assigned_before = 0;

  for (int iteration = 1; iteration <= o.em1.max_iterations; ++iteration) {
    result.iterations = iteration;
    const std::vector<int> usage = assign(planes, points, finite, o, unassigned);
    const double matched = 1.0 - static_cast<double>(unassigned.size()) / static_cast<double>(finite.size());
    // Planes still taking in points are progress too: a long wall grows by e_exp a side per
    // E-step, and stopping mid-growth left it short.
    const std::size_t assigned = finite.size() - unassigned.size();
    if (assigned > assigned_before) last_progress = std::max(last_progress, iteration);
    assigned_before = assigned;
    if (matched >= o.em1.done_fraction || iteration - last_progress > o.em1.patience) break;
    if (iteration == o.em1.max_iterations) break;  // the final pass below refits and culls

    // New random planes from the unassigned points, none sharing a point.
    std::fill(taken.begin(), taken.end(), 0);
    std::vector<int> free_points = unassigned;
    int seeds = 0;
    for (int attempt = 0; attempt < o.seed_attempts && seeds < o.em1.seeds_per_iteration; ++attempt) {
      std::erase_if(free_points, [&](int i) { return taken[static_cast<std::size_t>(i)] != 0; });
      if (free_points.size() < 3) break;
      const int start = free_points[random.below(free_points.size())];
      std::optional<EmPlane> fresh = seed_plane(points, start, free_points, o);
      if (!fresh) continue;
      for (int i : fresh->points) taken[static_cast<std::size_t>(i)] = 1;
      planes.push_back(std::move(*fresh));
      ++seeds;
    }

    // M-step: planes whose points lost their plane (collinear) are dropped.
    std::erase_if(planes, [&](EmPlane& plane) { return !refit(plane, points); });
    merge_planes(planes, points, o);
    cull_min_support(planes, o, o.em1.cull_age);
    cull_exclusivity(planes, points.size(), o, o.em1.cull_age);
    for (EmPlane& plane : planes)
      if (plane.age >= o.em1.cull_age && !plane.established) {
        plane.established = true;
        last_progress = iteration;
      }
  }

  std::erase_if(planes, [&](EmPlane& plane) { return !refit(plane, points); });
  merge_planes(planes, points, o);
  cull_min_support(planes, o, 0);
  cull_exclusivity(planes, points.size(), o, 0);
  tight_refit(planes, points, o);
  set_rectangles(planes, points, o);
  return result;
}

}  // namespace relslam::em
