#include "relslam/em/merging.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace relslam::em {

bool mergeable(const EmPlane& a, const EmPlane& b, const EmOptions& o) {
  const double cosine = a.normal.dot(b.normal);
  if (!(std::abs(cosine) >= std::cos(o.merge_angle_rad))) return false;
  // Deviation (thesis 3.5 compares the offsets d at the origin): the planes' distances at each
  // other's centroids. Two fits of one wall differing by a few degrees have offsets at the
  // robot that differ by distance × angle (0.5 at 5 units and 6°), so the origin test kept
  // pieces of one wall apart on noisy frames; near the points, where they must agree, they do.
  const double apart = std::max(std::abs(a.distance(b.centroid)), std::abs(b.distance(a.centroid)));
  const double d_in = std::max(inlier_distance_at(o, a.centroid), inlier_distance_at(o, b.centroid));
  if (!(apart <= o.merge_offset_factor * d_in)) return false;
  const Eigen::Vector3d margin = Eigen::Vector3d::Constant(o.bound_expansion);
  const Eigen::AlignedBox3d wide_a(a.box.min() - margin, a.box.max() + margin);
  const Eigen::AlignedBox3d wide_b(b.box.min() - margin, b.box.max() + margin);
  return wide_a.intersects(wide_b);
}

int merge_planes(std::vector<EmPlane>& planes, std::span<const Eigen::Vector3d> points, const EmOptions& o) {
  return merge_planes_where(planes, points, [&](const EmPlane& a, const EmPlane& b) { return mergeable(a, b, o); });
}

int merge_planes_where(std::vector<EmPlane>& planes, std::span<const Eigen::Vector3d> points,
                       const std::function<bool(const EmPlane&, const EmPlane&)>& same_surface) {
  int merges = 0;
  for (std::size_t i = 0; i < planes.size(); ++i) {
    bool grew = true;
    while (grew) {  // a grown plane may now reach planes it did not before
      grew = false;
      for (std::size_t j = i + 1; j < planes.size(); ++j) {
        if (!same_surface(planes[i], planes[j])) continue;
        EmPlane& into = planes[i];
        std::vector<int> joined;
        std::set_union(into.points.begin(), into.points.end(), planes[j].points.begin(), planes[j].points.end(),
                       std::back_inserter(joined));
        EmPlane merged = into;
        merged.points = std::move(joined);
        merged.age = std::max(into.age, planes[j].age);
        merged.established = into.established || planes[j].established;
        if (!refit(merged, points)) continue;  // cannot happen for two planes; kept apart if it does
        into = std::move(merged);
        planes.erase(planes.begin() + static_cast<std::ptrdiff_t>(j));
        ++merges;
        grew = true;
        break;
      }
    }
  }
  return merges;
}

}  // namespace relslam::em
