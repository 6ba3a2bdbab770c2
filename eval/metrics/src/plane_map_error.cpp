#include "relslam/eval/metrics/plane_map_error.hpp"

#include <cmath>
#include <utility>

namespace relslam::eval {

PlaneError plane_error(const PlaneObject& mapped, const PlaneObject& front) {
  // A plane of the wall's back face (a two-sided wall, or no back-face culling) has its key
  // points the other way round: it is scored against the wall as seen from behind.
  PlaneObject wall = front;
  if (mapped.normal().dot(front.normal()) < 0) std::swap(wall.a, wall.b);
  PlaneError e;
  e.ends = 0.5 * ((mapped.a - wall.a).norm() + (mapped.b - wall.b).norm());
  e.angle_rad = std::abs(wrap_angle(mapped.angle() - wall.angle()));
  e.perpendicular = std::abs(wall.normal().dot(mapped.midpoint()) + wall.offset());
  e.length_ratio = mapped.length() / wall.length();
  return e;
}

PlanarPoseError planar_pose_error(const PlanarPose& estimate, const PlanarPose& truth) {
  PlanarPoseError e;
  e.axes = estimate.translation - truth.translation;
  e.position = e.axes.norm();
  e.heading_rad = std::abs(wrap_angle(estimate.heading - truth.heading));
  return e;
}

void WallVotes::add(int plane, int wall) {
  if (plane < 0 || wall < 0) return;
  if (static_cast<std::size_t>(plane) >= votes_.size()) votes_.resize(static_cast<std::size_t>(plane) + 1);
  ++votes_[plane][wall];
}

int WallVotes::wall_of(int plane) const {
  if (plane < 0 || static_cast<std::size_t>(plane) >= votes_.size()) return -1;
  int best = -1, count = 0;
  for (const auto& [wall, n] : votes_[plane])  // ascending wall ids: a tie keeps the lower one
    if (n > count) best = wall, count = n;
  return best;
}

PlaneMapError plane_map_error(const std::vector<std::pair<int, PlaneObject>>& map, const WallVotes& votes,
                              const std::vector<PlaneObject>& walls) {
  PlaneMapError out;
  for (const auto& [id, plane] : map) {
    const int wall = votes.wall_of(id);
    if (wall < 0 || static_cast<std::size_t>(wall) >= walls.size()) continue;
    out.sum += plane_error(plane, walls[wall]).ends;
    ++out.scored;
  }
  out.mean = out.scored ? out.sum / out.scored : 0.0;
  return out;
}

}  // namespace relslam::eval
