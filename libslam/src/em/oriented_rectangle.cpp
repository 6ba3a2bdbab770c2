#include "relslam/em/oriented_rectangle.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace relslam::em {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Eigen::Vector2d xz(const Eigen::Vector3d& p) { return {p.x(), p.z()}; }

// The rectangle along `tangent` through `origin` covering the points.
OrientedRectangle extent_along(std::span<const Eigen::Vector3d> points, std::span<const int> indices,
                               const Eigen::Vector2d& origin, const Eigen::Vector2d& tangent) {
  OrientedRectangle r{origin, tangent, kInf, -kInf, kInf, -kInf};
  for (int i : indices) {
    const Eigen::Vector3d& p = points[static_cast<std::size_t>(i)];
    const double s = tangent.dot(xz(p) - origin);
    r.s_min = std::min(r.s_min, s);
    r.s_max = std::max(r.s_max, s);
    r.y_min = std::min(r.y_min, p.y());
    r.y_max = std::max(r.y_max, p.y());
  }
  return r;
}

// The search's score at one angle: the points in the frame turned by `angle` (axes a, b), their
// tight box, and Σ of each point's distance to the nearest of its four edge lines.
struct Turned {
  double score;
  double a_spread, b_spread;
};

Turned score_at(std::span<const Eigen::Vector3d> points, std::span<const int> indices, double angle) {
  const Eigen::Vector2d a(std::cos(angle), std::sin(angle)), b(-a.y(), a.x());
  double a_lo = kInf, a_hi = -kInf, b_lo = kInf, b_hi = -kInf;
  for (int i : indices) {
    const Eigen::Vector2d p = xz(points[static_cast<std::size_t>(i)]);
    a_lo = std::min(a_lo, a.dot(p));
    a_hi = std::max(a_hi, a.dot(p));
    b_lo = std::min(b_lo, b.dot(p));
    b_hi = std::max(b_hi, b.dot(p));
  }
  double score = 0.0;
  for (int i : indices) {
    const Eigen::Vector2d p = xz(points[static_cast<std::size_t>(i)]);
    const double pa = a.dot(p), pb = b.dot(p);
    score += std::min({pa - a_lo, a_hi - pa, pb - b_lo, b_hi - pb});
  }
  return {score, a_hi - a_lo, b_hi - b_lo};
}

}  // namespace

Eigen::Vector2d horizontal_tangent(const Eigen::Vector3d& n) {
  const Eigen::Vector2d u(n.z(), -n.x());
  const double norm = u.norm();
  return norm > 0.0 ? Eigen::Vector2d(u / norm) : Eigen::Vector2d::UnitX();
}

OrientedRectangle tangent_rectangle(std::span<const Eigen::Vector3d> points, std::span<const int> indices,
                                    const Eigen::Vector3d& normal, const Eigen::Vector3d& centroid) {
  return extent_along(points, indices, xz(centroid), horizontal_tangent(normal));
}

OrientedRectangle search_rectangle(std::span<const Eigen::Vector3d> points, std::span<const int> indices,
                                   const Eigen::Vector3d& normal, const Eigen::Vector3d& centroid, double step_rad,
                                   int passes) {
  // Pass 1 covers [0°, 180°): beyond, the box repeats with its axes swapped.
  double best = 0.0, best_score = kInf, lo = 0.0, hi = std::numbers::pi - step_rad, step = step_rad;
  for (int pass = 0; pass < passes; ++pass) {
    const int steps = static_cast<int>(std::lround((hi - lo) / step));
    for (int k = 0; k <= steps; ++k) {
      const double angle = lo + k * step;
      const double score = score_at(points, indices, angle).score;
      if (score < best_score) best_score = score, best = angle;  // the first of equal scores
    }
    lo = best - step;
    hi = best + step;
    step /= 10.0;
  }
  // The box side the points spread along is the tangent; it is oriented like the normal's
  // tangent so that s runs from key point 1 to key point 2.
  const Turned t = score_at(points, indices, best);
  const Eigen::Vector2d a(std::cos(best), std::sin(best)), b(-a.y(), a.x());
  Eigen::Vector2d tangent = t.a_spread >= t.b_spread ? a : b;
  if (tangent.dot(horizontal_tangent(normal)) < 0.0) tangent = -tangent;
  return extent_along(points, indices, xz(centroid), tangent);
}

OrientedRectangle box_corner_rectangle(std::span<const Eigen::Vector3d> points, std::span<const int> indices,
                                       const Eigen::Vector3d& normal, const Eigen::Vector3d& centroid) {
  Eigen::AlignedBox3d box;
  for (int i : indices) box.extend(points[static_cast<std::size_t>(i)]);
  std::array<Eigen::Vector3d, 8> corners;
  for (int c = 0; c < 8; ++c) corners[static_cast<std::size_t>(c)] = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c));
  const double offset = -normal.dot(centroid);
  auto distance = [&](const Eigen::Vector3d& p) { return std::abs(normal.dot(p) + offset); };
  std::stable_sort(corners.begin(), corners.end(),
                   [&](const Eigen::Vector3d& p, const Eigen::Vector3d& q) { return distance(p) < distance(q); });
  // Corners as close as the fourth count too: a box flat against an axis-aligned wall has all 8
  // corners on the plane, and any 4 of them might not span it.
  const double limit = distance(corners[3]) + 1e-12 * (1.0 + box.diagonal().norm());
  std::vector<int> closest;
  for (int c = 0; c < 8; ++c)
    if (distance(corners[static_cast<std::size_t>(c)]) <= limit) closest.push_back(c);
  return extent_along(corners, closest, xz(centroid), horizontal_tangent(normal));
}

}  // namespace relslam::em
