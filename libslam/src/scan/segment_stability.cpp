#include "relslam/scan/segment_stability.hpp"

#include <algorithm>
#include <cmath>

namespace relslam::scan {
namespace {

double line_distance(const PlaneObject& plane, const Eigen::Vector2d& p) {
  return std::abs(plane.normal().dot(p) + plane.offset());
}

bool same_wall(const PlaneObject& a, const PlaneObject& b, const CounterpartBounds& bounds) {
  if (a.normal().dot(b.normal()) < std::cos(bounds.max_angle_rad)) return false;
  if (line_distance(a, b.midpoint()) > bounds.max_offset || line_distance(b, a.midpoint()) > bounds.max_offset)
    return false;
  return overlap(a, b) > 0;
}

}  // namespace

double overlap(const PlaneObject& a, const PlaneObject& b) {
  const Eigen::Vector2d u = a.tangent();
  const double a0 = 0, a1 = a.length();
  const double b0 = u.dot(b.a - a.a), b1 = u.dot(b.b - a.a);
  return std::min(a1, std::max(b0, b1)) - std::max(a0, std::min(b0, b1));
}

bool has_counterpart(const PlaneObject& current, const std::vector<PlaneObject>& previous,
                     const PlanarPose& previous_T_current, const CounterpartBounds& bounds) {
  const PlaneObject moved = current.transformed(previous_T_current);
  return std::any_of(previous.begin(), previous.end(),
                     [&](const PlaneObject& p) { return same_wall(moved, p, bounds); });
}

int counterparts(const std::vector<PlaneObject>& current, const std::vector<PlaneObject>& previous,
                 const PlanarPose& previous_T_current, const CounterpartBounds& bounds) {
  return static_cast<int>(std::count_if(current.begin(), current.end(), [&](const PlaneObject& c) {
    return has_counterpart(c, previous, previous_T_current, bounds);
  }));
}

}  // namespace relslam::scan
