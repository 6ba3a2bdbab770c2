#pragma once
// The sensor's viewing volume in the robot frame. Part of relslam/sim: Eigen only.

#include "relslam/core/option_fields.hpp"

#include <Eigen/Core>
#include <cmath>
#include <numbers>
#include <optional>
#include <string_view>

namespace relslam::sim {

// Largest length a sim key may give (frustum and world options alike), units: far beyond the
// thesis's world (a loop of 1145 units, a band of 15 either side), yet small enough that
// positions, their differences and squares stay finite and precise in doubles. 1e308 gave NaN
// ground truth and observations.
inline constexpr double kMaxLength = 1e6;

// How the frustum is closed at the far end.
enum class FarCap {
  Plane,  // z <= far: the flat far plane of the thesis's Chapter 4 trapezoid frusta
  Range,  // |p| <= far: a range-limited sensor (corners are then no farther than ahead)
};
std::string_view to_string(FarCap cap);
std::optional<FarCap> parse_far_cap(std::string_view name);

// A horizontal trapezoid extruded vertically in the robot frame
// (+x left, +y up, +z forward). Culling is applied to the *noisy* points (thesis 4.2.1): with a
// symmetric height band this reproduces the thesis's unbiased vertical behaviour (6.6.1).
struct Frustum {
  double near = 1.0;   // units; closer points are not seen [C]
  double far = 100.0;  // units; forward limit [C], gives ~0.97·density visible points
  // Half the horizontal field of view; 45° gives a 90° view [C].
  double half_angle_rad = std::numbers::pi / 4.0;
  // Vertical half-extent |y| <= half_height; equal to the band's half height so culling
  // is symmetric (thesis 6.6.1) [I].
  double half_height = 5.0;
  FarCap far_cap = FarCap::Plane;  // [C] a prism

  // The tests with the trigonometry done once: the simulator runs them millions of times.
  struct Prepared {
    double near, far, half_height, tan_half_angle, side_margin_factor;
    bool range_cap;
    bool contains(const Eigen::Vector3d& p) const {
      if (p.z() < near || p.z() > far) return false;
      if (std::abs(p.x()) > p.z() * tan_half_angle) return false;
      if (std::abs(p.y()) > half_height) return false;
      return !range_cap || p.squaredNorm() <= far * far;
    }
    // False only if no point within `margin` (any direction) of p can be inside: lets the
    // simulator skip drawing noise for points that cannot become visible. Each face moves
    // outwards by `margin`; a side face x = z·tan(a) moves by margin / cos(a).
    bool may_contain(const Eigen::Vector3d& p, double margin) const {
      if (p.z() < near - margin || p.z() > far + margin) return false;
      if (std::abs(p.x()) > p.z() * tan_half_angle + margin * side_margin_factor) return false;
      if (std::abs(p.y()) > half_height + margin) return false;
      return !range_cap || p.norm() <= far + margin;
    }
  };
  Prepared prepare() const;

  bool contains(const Eigen::Vector3d& p_robot) const { return prepare().contains(p_robot); }
  // Largest distance from the sensor to any point inside (for MRPT's maxSensorDistance).
  double max_range() const;
  // Full vertical opening angle seen from the sensor (for MRPT's fieldOfView_pitch).
  double vertical_field_of_view_rad() const;
};

// The scenario keys of the frustum (sim.frustum.*): help and checks per field.
void describe(OptionsOf<Frustum> auto& f, auto& fields) {
  fields.field("near", f.near, "nearest visible depth, units", at_least(0.0), at_most(kMaxLength));
  fields.field("far", f.far, "farthest visible depth, units", above(f.near, "near"),
               at_most(kMaxLength));
  fields.degrees("half_angle_deg", f.half_angle_rad, "half the horizontal field of view", above(0.0), at_most(89.0));
  fields.field("half_height", f.half_height, "visible height band |y| <= this, units", above(0.0),
               at_most(kMaxLength));
  fields.choice("far_cap", f.far_cap, "far end: flat plane z <= far, or range |p| <= far",
                {FarCap::Plane, FarCap::Range});
}

}  // namespace relslam::sim
