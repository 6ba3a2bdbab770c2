#include "relslam/em/plane_conversion.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace relslam::em {

std::string_view to_string(PlaneLabel label) {
  switch (label) {
    case PlaneLabel::Wall: return "wall";
    case PlaneLabel::Floor: return "floor";
    case PlaneLabel::Ceiling: return "ceiling";
    case PlaneLabel::Other: return "other";
  }
  return "?";
}

PlaneLabel label_of(const EmPlane& plane, const ConversionOptions& o) {
  const double ny = std::abs(plane.normal.y());
  if (ny <= o.max_vertical_normal) return PlaneLabel::Wall;
  if (std::hypot(plane.normal.x(), plane.normal.z()) <= o.max_vertical_normal)
    return plane.centroid.y() < 0.0 ? PlaneLabel::Floor : PlaneLabel::Ceiling;
  return PlaneLabel::Other;
}

ExtractedPlanes to_plane_objects(const EmResult& result, const EmOptions& o, int iteration) {
  struct Kept {
    PlaneObject plane;
    const std::vector<int>* support;
  };
  std::vector<Kept> kept;
  for (const EmPlane& em : result.planes) {
    if (static_cast<int>(em.points.size()) < o.min_support) continue;
    if (std::abs(em.normal.y()) > o.conversion.max_vertical_normal) continue;
    // Front towards the robot: n·(0 − c) >= 0 (the fit already does this; EM planes from
    // elsewhere need not).
    Eigen::Vector2d n(em.normal.x(), em.normal.z());
    const Eigen::Vector2d c(em.centroid.x(), em.centroid.z());
    if (n.dot(-c) < 0.0) n = -n;
    n.normalize();
    // u = (n_z, −n_x): the rectangle's tangent may have been found for the other sign.
    const Eigen::Vector2d u(n.y(), -n.x());
    const OrientedRectangle& r = em.rectangle;
    // The rectangle's ends, projected onto the flattened plane's line through the centroid.
    const double s0 = u.dot(r.at(r.s_min) - c), s1 = u.dot(r.at(r.s_max) - c);
    PlaneObject plane;
    plane.a = c + std::min(s0, s1) * u;
    plane.b = c + std::max(s0, s1) * u;
    plane.y_lo = r.y_min;
    plane.y_hi = r.y_max;
    plane.iteration = iteration;
    if (!(plane.length() >= o.conversion.min_length)) continue;
    kept.push_back({plane, &em.points});
  }
  std::stable_sort(kept.begin(), kept.end(),
                   [](const Kept& x, const Kept& y) { return x.support->size() > y.support->size(); });
  ExtractedPlanes out;
  out.frame.iteration = iteration;
  for (const Kept& k : kept) {
    out.frame.planes.push_back(k.plane);
    out.support.push_back(*k.support);
  }
  return out;
}

PlaneTruth extracted_plane_truth(const PlaneObject& plane, std::span<const int> support,
                                 std::span<const int> point_wall_ids, std::span<const TrueWallEnds> walls,
                                 double end_tolerance) {
  std::map<int, int> votes;
  for (int i : support) {
    const int id = point_wall_ids[static_cast<std::size_t>(i)];
    if (id >= 0) ++votes[id];
  }
  PlaneTruth truth;
  int best = 0;
  for (const auto& [id, count] : votes)
    if (count > best) best = count, truth.wall_id = id;  // ascending ids: ties keep the smaller
  truth.a_is_wall_end = truth.b_is_wall_end = false;
  for (const TrueWallEnds& w : walls) {
    if (w.wall_id != truth.wall_id) continue;
    auto near_end = [&](const Eigen::Vector2d& p) {
      return std::min((p - w.a).norm(), (p - w.b).norm()) <= end_tolerance;
    };
    truth.a_is_wall_end = near_end(plane.a);
    truth.b_is_wall_end = near_end(plane.b);
  }
  return truth;
}

}  // namespace relslam::em
