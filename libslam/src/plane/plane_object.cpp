#include "relslam/plane/plane_object.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace relslam::plane {
namespace {

// A plane's 3-D axis-aligned box (x, y up, z), widened by a margin (thesis 4.3.1: a vertical
// wall along an axis has no thickness).
struct Box {
  Eigen::Vector3d lo, hi;

  Box(const PlaneObject& p, double margin)
      : lo(std::min(p.a.x(), p.b.x()) - margin, p.y_lo - margin, std::min(p.a.y(), p.b.y()) - margin),
        hi(std::max(p.a.x(), p.b.x()) + margin, p.y_hi + margin, std::max(p.a.y(), p.b.y()) + margin) {}

  bool contains(const Eigen::Vector3d& q) const {
    return (q.array() >= lo.array()).all() && (q.array() <= hi.array()).all();
  }
  // Of this box's 8 corners and its centre, how many lie inside `other` (thesis 4.5: the centre
  // catches a tall box crossing a wide one with no corner inside).
  int points_inside(const Box& other) const {
    int inside = other.contains(0.5 * (lo + hi)) ? 1 : 0;
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d q(corner & 1 ? hi.x() : lo.x(), corner & 2 ? hi.y() : lo.y(), corner & 4 ? hi.z() : lo.z());
      inside += other.contains(q) ? 1 : 0;
    }
    return inside;
  }
};

// Overlap along `previous` of the two planes, as a share of the shorter one.
double tangent_overlap(const PlaneObject& previous, const PlaneObject& current) {
  const Eigen::Vector2d u = previous.tangent();
  const double s0 = u.dot(current.a - previous.a), s1 = u.dot(current.b - previous.a);
  const double overlap = std::min(previous.length(), std::max(s0, s1)) - std::max(0.0, std::min(s0, s1));
  return overlap / std::min(previous.length(), current.length());
}

}  // namespace

double match_plane(const PlaneObject& previous, const PlaneObject& current, const MatchBounds& bounds,
                   bool same_normal_direction) {
  // Rule 10: an opposite normal is another plane (the back of a thin wall).
  const double dot = previous.normal().dot(current.normal());
  const double aligned = same_normal_direction ? dot : std::abs(dot);
  const double min_dot = std::cos(bounds.max_normal_angle_rad);
  if (aligned < min_dot) return -1;
  // Offsets compare along the same normal direction (they flip with a flipped normal).
  double offset_change = std::abs(previous.offset() - (dot < 0 ? -current.offset() : current.offset()));
  if (bounds.rotation_about_midpoint) {
    const double along = std::abs(current.tangent().dot(current.midpoint()));
    offset_change = std::max(0.0, offset_change - along * std::sqrt(std::max(0.0, 1.0 - aligned * aligned)));
  }
  if (offset_change > bounds.max_offset_change) return -1;
  const Box box_previous(previous, bounds.box_margin), box_current(current, bounds.box_margin);
  const int inside = box_previous.points_inside(box_current) + box_current.points_inside(box_previous);
  if (inside == 0 || tangent_overlap(previous, current) < bounds.min_overlap_fraction) return -1;
  double gap_score = 25;
  if (bounds.max_iteration_gap >= 0) {
    const int gap = current.iteration - previous.iteration;
    if (gap > bounds.max_iteration_gap) return -1;
    gap_score = 25.0 * (1.0 - static_cast<double>(gap) / (bounds.max_iteration_gap + 1));
  }
  // thesis 4.3.1's score: each test contributes how comfortably it passed.
  const double normal_score = min_dot < 1 ? 25.0 * (aligned - min_dot) / (1.0 - min_dot) : 25.0;
  const double offset_score =
      bounds.max_offset_change > 0 ? 25.0 * (1.0 - offset_change / bounds.max_offset_change) : 25.0;
  return normal_score + offset_score + 25.0 * inside / 18.0 + gap_score;
}

Eigen::Vector2d key_point(const PlaneObject& plane, KeyPoint k) {
  if (k == KeyPoint::None) throw std::logic_error("key_point: no key point (KeyPoint::None)");
  return k == KeyPoint::Left ? plane.a : plane.b;
}

Eigen::Vector2d assumed_midpoint(const PlaneObject& plane, double length, KeyPoint k) {
  const double along = k == KeyPoint::Left ? 0.5 * length : -0.5 * length;
  return key_point(plane, k) + along * plane.tangent();
}

PlaneObject adjust_size(const PlaneObject& plane, double length, KeyPoint k) {
  PlaneObject out = plane;
  const Eigen::Vector2d u = plane.tangent();
  if (k == KeyPoint::Left)
    out.b = plane.a + length * u;
  else if (k == KeyPoint::Right)
    out.a = plane.b - length * u;
  else
    throw std::logic_error("adjust_size: no key point to grow from (KeyPoint::None)");
  return out;
}

PlanarPose reanchor(const PlanarPose& pose, double length, double new_length, KeyPoint k) {
  if (k == KeyPoint::None) return pose;
  const double s = k == KeyPoint::Left ? 1.0 : -1.0;
  return pose * PlanarPose{{s * 0.5 * (new_length - length), 0.0}, 0.0};
}

PlanarPose calculate_offset(const PlaneObject& mapped, const PlaneObject& observed) {
  return mapped.pose() * observed.pose().inverse();
}

}  // namespace relslam::plane
