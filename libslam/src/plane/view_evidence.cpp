// Evidence against a place for relocalisation (view_evidence.hpp): the mapped walls the field of
// view should show there, and the planes in view that would pass through mapped walls.

#include "relslam/plane/view_evidence.hpp"

#include "relslam/core/frustum_depth.hpp"

#include <cmath>
#include <optional>
#include <vector>

namespace relslam::plane {
namespace {

// Where the segments p→p2 and q→q2 cross, as (share of p→p2, share of q→q2); nullopt when they
// are parallel.
std::optional<Eigen::Vector2d> crossing(const Eigen::Vector2d& p, const Eigen::Vector2d& p2, const Eigen::Vector2d& q,
                                        const Eigen::Vector2d& q2) {
  const Eigen::Vector2d r = p2 - p, s = q2 - q;
  const double denominator = r.x() * s.y() - r.y() * s.x();
  if (std::abs(denominator) < 1e-12) return std::nullopt;
  const Eigen::Vector2d w = q - p;
  return Eigen::Vector2d((w.x() * s.y() - w.y() * s.x()) / denominator, (w.x() * r.y() - w.y() * r.x()) / denominator);
}

// Whether a wall (or a plane in view) other than `self` stands between the robot and p_robot, by
// more than `margin` before it: the sensor with occlusion does not see p_robot then.
bool hidden(const Eigen::Vector2d& p, std::span<const PlaneObject> walls, const PlaneObject* self, double margin) {
  const double before = 1.0 - margin / std::max(p.norm(), margin);
  for (const PlaneObject& w : walls) {
    if (&w == self) continue;
    const std::optional<Eigen::Vector2d> t = crossing(Eigen::Vector2d::Zero(), p, w.a, w.b);
    if (t && t->x() > 0 && t->x() < before && t->y() >= 0 && t->y() <= 1) return true;
  }
  return false;
}

// Whether a plane in view lies on `wall`'s line (both robot frame) and reaches p_robot along it.
bool covers(const PlaneObject& seen, const PlaneObject& wall, const Eigen::Vector2d& p, double reach,
            const CoverBounds& bounds) {
  if (seen.normal().dot(wall.normal()) < std::cos(bounds.angle_rad)) return false;
  const Eigen::Vector2d n = wall.normal();
  if (std::abs(n.dot(seen.a - wall.a)) > bounds.offset || std::abs(n.dot(seen.b - wall.a)) > bounds.offset)
    return false;
  const double along = seen.tangent().dot(p - seen.a);
  return along >= -reach && along <= seen.length() + reach;
}

// A mapped wall (robot frame) of which more than max_unseen, edge_margin inside the footprint,
// should be in view and is not covered by the planes in view.
bool unseen(const PlaneObject& wall, std::span<const PlaneObject> seen, std::span<const PlaneObject> occluders,
            const FieldOfView& view, const ViewEvidenceOptions& o, const CoverBounds& bounds) {
  // A wall's back face is not seen, nor a wall farther off than the footprint reaches.
  if (view.front_face_only && wall.offset() <= 0) return false;
  const double length = wall.length();
  if ((wall.midpoint()).norm() > view.far / std::cos(view.half_angle_rad) + 0.5 * length) return false;
  const int samples = static_cast<int>(std::floor(length / o.sample_step));
  int expected = 0, covered = 0;
  for (int k = 0; k <= samples; ++k) {
    const Eigen::Vector2d p = wall.a + (k * o.sample_step) * wall.tangent();
    if (frustum_depth(p, view.half_angle_rad, view.near, view.far, view.radial) < o.edge_margin) continue;
    if (view.occlusion && hidden(p, occluders, &wall, o.edge_margin)) continue;
    ++expected;
    for (const PlaneObject& s : seen)
      if (covers(s, wall, p, o.edge_margin, bounds)) {
        ++covered;
        break;
      }
  }
  return (expected - covered) * o.sample_step > o.max_unseen;
}

// Whether a plane in view passes through a mapped wall, more than `margin` inside both.
bool crosses(const PlaneObject& seen, const PlaneObject& wall, double margin) {
  const std::optional<Eigen::Vector2d> t = crossing(seen.a, seen.b, wall.a, wall.b);
  if (!t) return false;
  const double ls = seen.length(), lw = wall.length();
  return t->x() * ls > margin && (1 - t->x()) * ls > margin && t->y() * lw > margin && (1 - t->y()) * lw > margin;
}

}  // namespace

std::string_view to_string(ViewConflict conflict) {
  switch (conflict) {
    case ViewConflict::None: return "none";
    case ViewConflict::UnseenWall: return "unseen_wall";
    case ViewConflict::Crossing: return "crossing";
  }
  return "?";
}

double FieldOfView::depth(const Eigen::Vector2d& p_robot) const {
  return frustum_depth(p_robot, half_angle_rad, near, far, radial);
}

ViewConflict view_conflict(const PlanarPose& world_T_robot, std::span<const PlaneObject> seen,
                           std::span<const PlaneObject> map, const FieldOfView& view,
                           const ViewEvidenceOptions& options, const CoverBounds& cover) {
  if (!view.known) return ViewConflict::None;
  const PlanarPose robot_T_world = world_T_robot.inverse();
  std::vector<PlaneObject> walls;  // the map in the robot frame, then the planes in view (occluders)
  walls.reserve(map.size() + seen.size());
  for (const PlaneObject& m : map) walls.push_back(m.transformed(robot_T_world));
  for (const PlaneObject& s : seen)
    for (std::size_t w = 0; w < map.size(); ++w)
      if (crosses(s, walls[w], options.crossing_margin)) return ViewConflict::Crossing;
  walls.insert(walls.end(), seen.begin(), seen.end());
  for (std::size_t w = 0; w < map.size(); ++w)
    if (unseen(walls[w], seen, walls, view, options, cover)) return ViewConflict::UnseenWall;
  return ViewConflict::None;
}

}  // namespace relslam::plane
