#pragma once
// The shared parts of both EM variants (thesis 3.5.2, 3.5.3): the EM plane, its
// membership test and refit, the points' usage counters, and what an extraction returns.
// Eigen only.

#include "relslam/em/options.hpp"
#include "relslam/em/oriented_rectangle.hpp"
#include "relslam/em/tls_fit.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <span>
#include <vector>

namespace relslam::em {

// d_in for a point at p (the sensor at the origin): max(d_in, inlier_per_range2 · |p|²).
inline double inlier_distance_at(const EmOptions& o, const Eigen::Vector3d& p) {
  return std::max(o.inlier_distance, o.inlier_per_range2 * p.squaredNorm());
}

// One plane model. Invariant once refit() succeeded: normal is the TLS fit of `points`
// (ascending indices into the frame's points, no repeats), turned towards the sensor, and
// `box` is their tight axis-aligned box.
struct EmPlane {
  std::vector<int> points;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();
  double offset = 0.0;  // n·p + d = 0
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::AlignedBox3d box;
  int seed_point = -1;       // the random point it started from (EM2 grows from it)
  int age = 0;               // E-steps it has been through (EM1 culls only planes with age >= 1)
  bool established = false;  // has survived the culls once (EM1's stop rule)
  OrientedRectangle rectangle;  // set when the extraction finishes

  double distance(const Eigen::Vector3d& p) const { return normal.dot(p) + offset; }
  // The membership test (thesis 3.5): inside the box widened by `expansion` on every side, and
  // within `inlier_distance` of the plane.
  bool accepts(const Eigen::Vector3d& p, double inlier_distance, double expansion) const;
  // ... with the options' e_exp and d_in at p (inlier_distance_at).
  bool accepts(const Eigen::Vector3d& p, const EmOptions& o) const {
    return accepts(p, inlier_distance_at(o, p), o.bound_expansion);
  }
};

// Refits plane from its points (M-step) and sets its tight box; false (plane unchanged but for
// the box) when the points have no plane (fewer than 3, collinear).
bool refit(EmPlane& plane, std::span<const Eigen::Vector3d> points);
// The tight box of the plane's points.
void update_box(EmPlane& plane, std::span<const Eigen::Vector3d> points);

// How many planes own each point (the thesis's per-point usage counter): `count` entries.
std::vector<int> usage_counts(const std::vector<EmPlane>& planes, std::size_t count);

// The share of the plane's points no other plane owns (usage 1), 0 for an empty plane.
double exclusive_fraction(const EmPlane& plane, const std::vector<int>& usage);

// What one extraction returns: the planes (each with its rectangle) and what it took.
struct EmResult {
  std::vector<EmPlane> planes;
  int iterations = 0;      // EM iterations run
  int ignored_points = 0;  // non-finite input points, never assigned
};

// Hands each candidate point that no plane owns to the plane that accepts it (options' d_in and
// e_exp) and lies nearest, then refits the planes that took points; repeated while any point
// joins, at most `passes` times (each pass reaches e_exp further). Returns the points added.
// EM2's leftovers (em2.absorb_passes) [C].
int absorb_unassigned(std::vector<EmPlane>& planes, std::span<const Eigen::Vector3d> points,
                      std::span<const int> candidates, const EmOptions& options, int passes);

// Sets each plane's rectangle by options.rectangle (the extraction's last step).
void set_rectangles(std::vector<EmPlane>& planes, std::span<const Eigen::Vector3d> points, const EmOptions& options);

// The indices of the finite points: NaN or infinite input is left out, never a crash.
std::vector<int> finite_points(std::span<const Eigen::Vector3d> points);

}  // namespace relslam::em
