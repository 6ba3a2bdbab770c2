#include "relslam/em/coplanar_merging.hpp"

#include "relslam/em/merging.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace relslam::em {
namespace {

// The share of each plane's points the joint fit must hold within d_in [C]: EM's planes hold
// their points within d_in of their own fit, so a joint fit of one surface keeps nearly all;
// two surfaces' pieces leave one of them mostly outside.
constexpr double kCoplanarShare = 0.9;

// The distance between two axis-aligned boxes (0 where they overlap).
double box_gap(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b) {
  const Eigen::Vector3d below = (b.min() - a.max()).cwiseMax(0.0);
  const Eigen::Vector3d above = (a.min() - b.max()).cwiseMax(0.0);
  return (below + above).norm();
}

// The mean distance of the plane's points from the sensor (not its centroid's: a scan line's
// arc of the ground around the sensor has its centroid near it).
double mean_range(const EmPlane& plane, std::span<const Eigen::Vector3d> points) {
  double sum = 0;
  for (int i : plane.points) sum += points[static_cast<std::size_t>(i)].norm();
  return plane.points.empty() ? 0.0 : sum / static_cast<double>(plane.points.size());
}

bool holds(const PlaneFit& fit, const EmPlane& plane, std::span<const Eigen::Vector3d> points, const EmOptions& o) {
  std::size_t within = 0;
  for (int i : plane.points) {
    const Eigen::Vector3d& p = points[static_cast<std::size_t>(i)];
    within += std::abs(fit.normal.dot(p) + fit.offset) <= inlier_distance_at(o, p);
  }
  return static_cast<double>(within) >= kCoplanarShare * static_cast<double>(plane.points.size());
}

std::vector<int> joined(const EmPlane& a, const EmPlane& b) {
  std::vector<int> out;
  out.reserve(a.points.size() + b.points.size());
  std::set_union(a.points.begin(), a.points.end(), b.points.begin(), b.points.end(), std::back_inserter(out));
  return out;
}

}  // namespace

bool coplanar(const EmPlane& a, const EmPlane& b, std::span<const Eigen::Vector3d> points, const EmOptions& o,
              double gap_per_range) {
  const double range = std::min(mean_range(a, points), mean_range(b, points));
  if (!(box_gap(a.box, b.box) <= o.bound_expansion + gap_per_range * range)) return false;
  const std::vector<int> both = joined(a, b);
  const std::optional<PlaneFit> fit = fit_plane(points, both);
  return fit && holds(*fit, a, points, o) && holds(*fit, b, points, o);
}

int merge_coplanar(std::vector<EmPlane>& planes, std::span<const Eigen::Vector3d> points, const EmOptions& o,
                   double gap_per_range) {
  return merge_planes_where(planes, points, [&](const EmPlane& a, const EmPlane& b) {
    return coplanar(a, b, points, o, gap_per_range);
  });
}

}  // namespace relslam::em
