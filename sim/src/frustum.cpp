#include "relslam/sim/frustum.hpp"

#include <cmath>

namespace relslam::sim {

std::string_view to_string(FarCap cap) { return cap == FarCap::Plane ? "plane" : "range"; }

std::optional<FarCap> parse_far_cap(std::string_view name) {
  if (name == "plane") return FarCap::Plane;
  if (name == "range") return FarCap::Range;
  return std::nullopt;
}

Frustum::Prepared Frustum::prepare() const {
  return {near, far, half_height, std::tan(half_angle_rad), 1.0 / std::cos(half_angle_rad), far_cap == FarCap::Range};
}

double Frustum::max_range() const {
  const double corner_x = far * std::tan(half_angle_rad);
  const double plane_corner = std::sqrt(far * far + corner_x * corner_x + half_height * half_height);
  return far_cap == FarCap::Plane ? plane_corner : far;
}

double Frustum::vertical_field_of_view_rad() const { return 2.0 * std::atan2(half_height, near); }

}  // namespace relslam::sim
