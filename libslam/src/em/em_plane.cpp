#include "relslam/em/em_plane.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace relslam::em {

bool EmPlane::accepts(const Eigen::Vector3d& p, double inlier_distance, double expansion) const {
  const Eigen::Vector3d margin = Eigen::Vector3d::Constant(expansion);
  if ((p.array() < (box.min() - margin).array()).any() || (p.array() > (box.max() + margin).array()).any())
    return false;
  return std::abs(distance(p)) <= inlier_distance;
}

void update_box(EmPlane& plane, std::span<const Eigen::Vector3d> points) {
  plane.box.setEmpty();
  for (int i : plane.points) plane.box.extend(points[static_cast<std::size_t>(i)]);
}

bool refit(EmPlane& plane, std::span<const Eigen::Vector3d> points) {
  const std::optional<PlaneFit> fit = fit_plane(points, plane.points, &plane.box);
  if (!fit) return false;
  plane.normal = fit->normal;
  plane.offset = fit->offset;
  plane.centroid = fit->centroid;
  return true;
}

std::vector<int> usage_counts(const std::vector<EmPlane>& planes, std::size_t count) {
  std::vector<int> usage(count, 0);
  for (const EmPlane& plane : planes)
    for (int i : plane.points) ++usage[static_cast<std::size_t>(i)];
  return usage;
}

double exclusive_fraction(const EmPlane& plane, const std::vector<int>& usage) {
  if (plane.points.empty()) return 0.0;
  int own = 0;
  for (int i : plane.points) own += usage[static_cast<std::size_t>(i)] == 1;
  return static_cast<double>(own) / static_cast<double>(plane.points.size());
}

int absorb_unassigned(std::vector<EmPlane>& planes, std::span<const Eigen::Vector3d> points,
                      std::span<const int> candidates, const EmOptions& o, int passes) {
  int added = 0;
  std::vector<std::vector<int>> joining(planes.size());
  for (int pass = 0; pass < passes; ++pass) {
    const std::vector<int> usage = usage_counts(planes, points.size());
    for (std::vector<int>& j : joining) j.clear();
    for (int i : candidates) {
      if (usage[static_cast<std::size_t>(i)] != 0) continue;
      const Eigen::Vector3d& p = points[static_cast<std::size_t>(i)];
      std::size_t best = planes.size();
      double nearest = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < planes.size(); ++k) {
        if (!planes[k].accepts(p, o)) continue;
        const double d = std::abs(planes[k].distance(p));
        if (d < nearest) nearest = d, best = k;
      }
      if (best < planes.size()) joining[best].push_back(i);  // candidates ascend: so does each list
    }
    int joined = 0;
    for (std::size_t k = 0; k < planes.size(); ++k) {
      if (joining[k].empty()) continue;
      EmPlane next = planes[k];
      next.points.clear();
      std::set_union(planes[k].points.begin(), planes[k].points.end(), joining[k].begin(), joining[k].end(),
                     std::back_inserter(next.points));
      if (!refit(next, points)) continue;
      planes[k] = std::move(next);
      joined += static_cast<int>(joining[k].size());
    }
    if (joined == 0) break;
    added += joined;
  }
  return added;
}

void set_rectangles(std::vector<EmPlane>& planes, std::span<const Eigen::Vector3d> points, const EmOptions& o) {
  for (EmPlane& plane : planes) {
    switch (o.rectangle) {
      case RectangleFit::TangentProjection:
        plane.rectangle = tangent_rectangle(points, plane.points, plane.normal, plane.centroid);
        break;
      case RectangleFit::RotationSearch:
        plane.rectangle =
            search_rectangle(points, plane.points, plane.normal, plane.centroid, o.search_step_rad, o.search_passes);
        break;
      case RectangleFit::BoxCorners:
        plane.rectangle = box_corner_rectangle(points, plane.points, plane.normal, plane.centroid);
        break;
    }
  }
}

std::vector<int> finite_points(std::span<const Eigen::Vector3d> points) {
  std::vector<int> finite;
  finite.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].allFinite()) finite.push_back(static_cast<int>(i));
  return finite;
}

}  // namespace relslam::em
