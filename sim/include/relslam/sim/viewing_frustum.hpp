#pragma once
// The planar world's viewing frustum: its horizontal footprint in the robot frame and the
// clipping of a wall segment to it (thesis 4.4.2.2 `ViewingFrustum`).
// Part of relslam/sim: Eigen only.

#include "relslam/core/option_issue.hpp"

#include <Eigen/Core>

#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace relslam::sim {

enum class FrustumShape {
  // Trapezoid {near <= x <= far, |z| <= x·tan α}: the thesis's frustum. Its far corners lie
  // farther away (far / cos α) than straight ahead, which the thesis blames for the "frustum
  // failure" of Fig. 89 and the small error of Fig. 105 [T].
  Planar,
  // Sector {|p| <= far, |atan2(z, x)| <= α, x >= near}: one way to "expand the frustum so the
  // problem does not occur", the thesis's fix for Fig. 89 [R].
  Radial,
};
std::string_view to_string(FrustumShape shape);
std::optional<FrustumShape> parse_frustum_shape(std::string_view name);

// The visible piece of a segment a→b: the points a + t·(b − a) for t in [enter, exit],
// 0 <= enter <= exit <= 1. An end is a frustum cut exactly when its parameter is not 0 or 1.
struct SegmentClip {
  double enter = 0.0;
  double exit = 1.0;
  bool cuts_a() const { return enter > 0.0; }
  bool cuts_b() const { return exit < 1.0; }
};

// The robot sits at the origin looking along +x; z is lateral. No vertical
// clipping: walls span their whole height in view, because the algorithm treats height as
// static [T 4.2.3] (thesis 4.4.2).
struct ViewingFrustum {
  FrustumShape shape = FrustumShape::Planar;  // the thesis's trapezoid [T]
  // Half the horizontal field of view; must stay below 90° so the footprint is convex and
  // lies in front of the robot. Presets give the "small" value [R].
  double half_angle_rad = 30.0 * std::numbers::pi / 180.0;
  double near = 0.1;  // units; closer parts of a wall are not seen [R]
  double far = 7.0;   // units; the small frustum of the thesis's many-planes runs [R]

  // The "small" frustum of Maps C and D (thesis ch. 5 "many planes, small frustum") [R values].
  static ViewingFrustum small() { return {}; }
  // The "large" frustum of Map E (thesis motion-model runs) [R values].
  static ViewingFrustum large() { return {FrustumShape::Planar, 35.0 * std::numbers::pi / 180.0, 0.1, 30.0}; }

  bool contains(const Eigen::Vector2d& p_robot) const;
  // How far p_robot lies inside the footprint: its distance to the nearest edge (near line, far
  // line or circle, a side), negative outside. A sensor that reports only points can tell by it
  // which ends of a wall it found were cut by its field of view.
  double depth(const Eigen::Vector2d& p_robot) const;
  // The part of the segment a→b (robot frame) inside the footprint, boundary included, or
  // nothing when the segment misses it. Cyrus–Beck against the straight edges; for Radial the
  // far circle is intersected exactly.
  std::optional<SegmentClip> clip(const Eigen::Vector2d& a_robot, const Eigen::Vector2d& b_robot) const;
};

// A preset by name ("small", "large").
std::optional<ViewingFrustum> frustum_preset(std::string_view name);

// Every violated constraint; fields are relative to the frustum ("half_angle_deg", "far").
std::vector<OptionIssue> check(const ViewingFrustum& frustum);

}  // namespace relslam::sim
