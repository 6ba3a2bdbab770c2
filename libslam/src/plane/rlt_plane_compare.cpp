#include "relslam/plane/rlt_plane_compare.hpp"

#include "pose_mean.hpp"
#include "relslam/plane/rlt_plane.hpp"
#include "relslam/plane/rlt_plane_interval.hpp"

#include <algorithm>

namespace relslam::plane {
namespace {

// The heading of `second` relative to `first` as (cos, sin) of the angle between their
// tangents: their dot and cross products, so the circular mean needs no atan2 per sample.
Eigen::Vector2d relative_direction(const Eigen::Vector2d& u_first, const Eigen::Vector2d& u_second) {
  return {u_first.dot(u_second), u_first.x() * u_second.y() - u_first.y() * u_second.x()};
}

// Rule 3's offset of one iteration, accumulated into `mean`.
void add_offset(const PlaneObject& first, const PlaneObject& second, bool rotate_to_first, PoseMean& mean) {
  const Eigen::Vector2d u1 = first.tangent();
  const Eigen::Vector2d d = second.midpoint() - first.midpoint();
  // Rot(−θ₁)·d = (u₁·d, n₁·d) with n₁ = Rot(+90°)u₁.
  const Eigen::Vector2d offset = rotate_to_first ? Eigen::Vector2d(u1.dot(d), u1.x() * d.y() - u1.y() * d.x()) : d;
  const Eigen::Vector2d angle = relative_direction(u1, second.tangent());
  mean.add(offset, angle.x(), angle.y());
}

}  // namespace

PlanarPose plane_offset(const PlaneObject& first, const PlaneObject& second, bool rotate_to_first) {
  PoseMean one;
  add_offset(first, second, rotate_to_first, one);
  return one.mean();
}

CompareResult compare_planes(const RltPlane& first, const RltPlane& second, bool rotate_to_first,
                             const RltPlaneInterval* within) {
  CompareResult result;
  if (first.size() == 0 || second.size() == 0) return result;
  // Merge walk over the two circular arrays from the first iteration both still store.
  const int start = std::max(first[0].iteration, second[0].iteration);
  int i = first.lower_bound(start), j = second.lower_bound(start);
  auto run = within ? within->runs().begin() : std::vector<RltInterval>::const_iterator{};
  PoseMean mean;
  while (i < first.size() && j < second.size()) {
    const PlaneObject& p1 = first[i];
    const PlaneObject& p2 = second[j];
    if (p1.iteration != p2.iteration) {
      (p1.iteration < p2.iteration ? i : j) += 1;
      continue;
    }
    ++i, ++j;
    const int t = p1.iteration;
    if (within) {  // IntervalMode::Group: only inside the group's common interval
      while (run != within->runs().end() && run->end < t) ++run;
      if (run == within->runs().end()) break;
      if (t < run->start) continue;
    }
    add_offset(p1, p2, rotate_to_first, mean);
    result.length1 = std::max(result.length1, p1.length());
    result.length2 = std::max(result.length2, p2.length());
    result.height1 = std::max(result.height1, p1.height());
    result.height2 = std::max(result.height2, p2.height());
    if (result.samples == 0) result.interval.start = t;
    result.interval.end = t;
    ++result.samples;
  }
  result.valid = result.samples > 0;
  result.delta = mean.mean();
  return result;
}

}  // namespace relslam::plane
