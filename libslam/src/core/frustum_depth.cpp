#include "relslam/core/frustum_depth.hpp"

#include <algorithm>
#include <cmath>

namespace relslam {

double frustum_depth(const Eigen::Vector2d& p, double half_angle_rad, double near, double far, bool radial) {
  // The sides z = ±x·tan α of both shapes, as distances along their inward normals.
  const double side = p.x() * std::sin(half_angle_rad) - std::abs(p.y()) * std::cos(half_angle_rad);
  const double far_edge = radial ? far - p.norm() : far - p.x();
  return std::min({p.x() - near, far_edge, side});
}

}  // namespace relslam
