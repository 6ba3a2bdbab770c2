#include "relslam/sim/viewing_frustum.hpp"
#include "relslam/core/frustum_depth.hpp"
#include "relslam/core/option_fields.hpp"

#include <algorithm>
#include <cmath>

namespace relslam::sim {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// Cyrus–Beck on one half-plane normal·p <= bound, for p(t) = a + t·d: narrows [enter, exit]
// and returns false when the segment lies wholly outside.
bool clip_half_plane(const Eigen::Vector2d& normal, double bound, const Eigen::Vector2d& a, const Eigen::Vector2d& d,
                     SegmentClip& clip) {
  const double start = normal.dot(a) - bound;  // > 0: a is outside
  const double rate = normal.dot(d);
  if (rate == 0.0) return start <= 0.0;  // parallel to the edge: all in or all out
  const double t = -start / rate;
  if (rate > 0.0)
    clip.exit = std::min(clip.exit, t);
  else
    clip.enter = std::max(clip.enter, t);
  return clip.enter <= clip.exit;
}

// |a + t·d| <= radius: the roots of |d|²t² + 2(a·d)t + |a|² − r² = 0 bound the inside.
bool clip_circle(double radius, const Eigen::Vector2d& a, const Eigen::Vector2d& d, SegmentClip& clip) {
  const double qa = d.squaredNorm(), qb = a.dot(d), qc = a.squaredNorm() - radius * radius;
  if (qa == 0.0) return qc <= 0.0;  // a point: in or out
  const double discriminant = qb * qb - qa * qc;
  if (discriminant < 0.0) return false;
  const double root = std::sqrt(discriminant);
  // The numerically stable pair of roots (no cancellation between qb and root).
  const double q = qb >= 0.0 ? -(qb + root) : -(qb - root);
  double t1 = q / qa, t2 = q != 0.0 ? qc / q : -t1;
  if (t1 > t2) std::swap(t1, t2);
  clip.enter = std::max(clip.enter, t1);
  clip.exit = std::min(clip.exit, t2);
  return clip.enter <= clip.exit;
}

}  // namespace

std::string_view to_string(FrustumShape shape) { return shape == FrustumShape::Planar ? "planar" : "radial"; }

std::optional<FrustumShape> parse_frustum_shape(std::string_view name) {
  for (FrustumShape shape : {FrustumShape::Planar, FrustumShape::Radial})
    if (name == to_string(shape)) return shape;
  return std::nullopt;
}

bool ViewingFrustum::contains(const Eigen::Vector2d& p) const {
  if (p.x() < near || std::abs(p.y()) > p.x() * std::tan(half_angle_rad)) return false;
  return shape == FrustumShape::Planar ? p.x() <= far : p.squaredNorm() <= far * far;
}

double ViewingFrustum::depth(const Eigen::Vector2d& p) const {
  return frustum_depth(p, half_angle_rad, near, far, shape == FrustumShape::Radial);
}

std::optional<SegmentClip> ViewingFrustum::clip(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  const Eigen::Vector2d d = b - a;
  const double tan_half = std::tan(half_angle_rad);
  SegmentClip clip;
  // The side edges z = ±x·tan α and the near line, as outward normals: n·p <= bound inside.
  const bool inside =
      clip_half_plane({-1.0, 0.0}, -near, a, d, clip) && clip_half_plane({-tan_half, 1.0}, 0.0, a, d, clip) &&
      clip_half_plane({-tan_half, -1.0}, 0.0, a, d, clip) &&
      (shape == FrustumShape::Planar ? clip_half_plane({1.0, 0.0}, far, a, d, clip) : clip_circle(far, a, d, clip));
  if (!inside) return std::nullopt;
  return clip;
}

std::optional<ViewingFrustum> frustum_preset(std::string_view name) {
  if (name == "small") return ViewingFrustum::small();
  if (name == "large") return ViewingFrustum::large();
  return std::nullopt;
}

std::vector<OptionIssue> check(const ViewingFrustum& f) {
  std::vector<OptionIssue> issues;
  // Below 90° the footprint is convex and in front of the robot, which the clipping assumes.
  const double half_angle_deg = f.half_angle_rad / kDegree;
  if (!(half_angle_deg > 0.0 && half_angle_deg < 90.0))
    issues.push_back({"half_angle_deg", "must be > 0 and < 90, got " + format_number(half_angle_deg)});
  at_least(0.0)(issues, "near", f.near);
  if (!(f.far > f.near) || !std::isfinite(f.far))
    issues.push_back({"far", "must be > near (" + format_number(f.near) + "), got " + format_number(f.far)});
  return issues;
}

}  // namespace relslam::sim
