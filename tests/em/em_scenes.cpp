#include "em_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace relslam::em::test {

sim::Wall facing_wall(int id, Eigen::Vector2d a, Eigen::Vector2d b, const Eigen::Vector2d& facing) {
  sim::Wall w = sim::Wall::between(id, a, b);
  if (w.normal().dot(facing) < 0) std::swap(w.a, w.b);
  return w;
}

namespace {

// Map D's split of a side from `from` to `to` (coordinate along the side): pieces of
// 4 with gaps of 1 from 0.5 after the start; a last shorter piece ending 0.5 before the end is
// kept if at least 1.5 long.
std::vector<std::pair<double, double>> split_side(double from, double to) {
  std::vector<std::pair<double, double>> pieces;
  double s = from + 0.5;
  while (s + 4 <= to - 0.5 + 1e-9) {
    pieces.emplace_back(s, s + 4);
    s += 5;
  }
  if (to - 0.5 - s >= 1.5 - 1e-9) pieces.emplace_back(s, to - 0.5);
  return pieces;
}

}  // namespace

sim::PlanarWorld office_loop() {
  sim::PlanarWorld world;
  int id = 0;
  // One rectangle's four sides in map order (bottom, right, top, left), facing in or out.
  auto rectangle = [&](double x0, double z0, double x1, double z1, bool inwards) {
    const double sign = inwards ? 1.0 : -1.0;
    for (auto [s0, s1] : split_side(x0, x1)) world.walls.push_back(facing_wall(id++, {s0, z0}, {s1, z0}, {0, sign}));
    for (auto [s0, s1] : split_side(z0, z1)) world.walls.push_back(facing_wall(id++, {x1, s0}, {x1, s1}, {-sign, 0}));
    for (auto [s0, s1] : split_side(x0, x1)) world.walls.push_back(facing_wall(id++, {s0, z1}, {s1, z1}, {0, -sign}));
    for (auto [s0, s1] : split_side(z0, z1)) world.walls.push_back(facing_wall(id++, {x0, s0}, {x0, s1}, {sign, 0}));
  };
  rectangle(0, 0, 30, 20, true);
  rectangle(3, 3, 27, 17, false);
  return world;
}

sim::PlanarWorld motion_room() {
  sim::PlanarWorld world;
  int id = 0;
  auto add = [&](Eigen::Vector2d a, Eigen::Vector2d b, Eigen::Vector2d facing) {
    world.walls.push_back(facing_wall(id++, a, b, facing));
  };
  add({0.5, 0}, {23.5, 0}, {0, 1});
  add({24, 0.5}, {24, 15.5}, {-1, 0});
  add({0.5, 16}, {23.5, 16}, {0, -1});
  add({0, 0.5}, {0, 15.5}, {1, 0});
  add({7, 5.5}, {11.5, 5.5}, {0, -1});
  add({12.5, 5.5}, {17, 5.5}, {0, -1});
  add({7, 10.5}, {11.5, 10.5}, {0, 1});
  add({12.5, 10.5}, {17, 10.5}, {0, 1});
  add({7, 5.5}, {7, 10.5}, {-1, 0});
  add({17, 5.5}, {17, 10.5}, {1, 0});
  return world;
}

FrameScore score(const sim::PlanarWorld& world, const sim::PointSimFrame& frame, const ExtractedPlanes& planes,
                 double sigma) {
  FrameScore out;
  const PlanarPose& pose = frame.truth.world_T_robot;
  std::vector<TrueWallEnds> ends;
  std::map<int, const sim::Wall*> by_id;
  for (const sim::Wall& w : world.walls) {
    ends.push_back({w.id, pose.inverse_apply(w.a), pose.inverse_apply(w.b)});
    by_id[w.id] = &w;
  }
  // The view of each wall: its points' positions along it (robot frame).
  std::map<int, std::vector<double>> along;
  for (std::size_t i = 0; i < frame.observation.points.size(); ++i) {
    const int id = frame.truth.wall_ids[i];
    const sim::Wall& w = *by_id.at(id);
    const Eigen::Vector2d a = pose.inverse_apply(w.a), b = pose.inverse_apply(w.b);
    const Eigen::Vector3d& p = frame.observation.points[i];
    along[id].push_back((b - a).normalized().dot(Eigen::Vector2d(p.x(), p.z()) - a));
  }
  for (auto& [id, s] : along) {
    const sim::Wall& w = *by_id.at(id);
    WallScore& ws = out.walls[id];
    ws.wall_id = id;
    ws.visible_points = static_cast<int>(s.size());
    const auto [lo, hi] = std::minmax_element(s.begin(), s.end());
    ws.visible_extent = *hi - *lo;
    const double n = static_cast<double>(s.size()), extent = std::max(ws.visible_extent, 1e-3);
    ws.expected_angle_rad = sigma * std::sqrt(12.0) / (extent * std::sqrt(n));
    const Eigen::Vector2d a = pose.inverse_apply(w.a), u = (pose.inverse_apply(w.b) - a).normalized();
    const double foot = -u.dot(a), centre = 0.5 * (*lo + *hi);  // along the wall from a
    ws.expected_offset = sigma / std::sqrt(n) + std::abs(centre - foot) * ws.expected_angle_rad;
  }

  out.planes = static_cast<int>(planes.frame.planes.size());
  std::map<int, std::size_t> largest;
  for (std::size_t i = 0; i < planes.frame.planes.size(); ++i) {
    const PlaneTruth t =
        extracted_plane_truth(planes.frame.planes[i], planes.support[i], frame.truth.wall_ids, ends, 0.15);
    if (t.wall_id < 0) {
      ++out.unlabelled_planes;
      continue;
    }
    WallScore& ws = out.walls[t.wall_id];
    ws.wall_id = t.wall_id;
    ++ws.planes;
    if (!largest.count(t.wall_id) || planes.support[i].size() > planes.support[largest[t.wall_id]].size())
      largest[t.wall_id] = i;
  }
  for (const auto& [id, i] : largest) {
    const PlaneObject& p = planes.frame.planes[i];
    const sim::Wall& w = *by_id.at(id);
    const Eigen::Vector2d a = pose.inverse_apply(w.a), b = pose.inverse_apply(w.b);
    const Eigen::Vector2d u = (b - a).normalized(), n(-u.y(), u.x());  // the wall's front, as seen
    WallScore& ws = out.walls[id];
    ws.normal_error_rad = std::acos(std::clamp(p.normal().dot(n), -1.0, 1.0));
    ws.offset_error = std::abs(p.offset() - (-n.dot(a)));
    const std::vector<double>& s = along[id];
    const auto [lo, hi] = std::minmax_element(s.begin(), s.end());
    const Eigen::Vector2d vis_a = a + *lo * u, vis_b = a + *hi * u;
    ws.end_error = std::max((p.a - vis_a).norm(), (p.b - vis_b).norm());
  }
  return out;
}

bool required(const WallScore& wall, const EmOptions& options, double min_extent) {
  return wall.visible_points >= options.min_support && wall.visible_extent >= min_extent;
}

std::string FrameScore::describe() const {
  std::ostringstream text;
  text << planes << " planes;";
  for (const auto& [id, w] : walls)
    text << " wall " << id << ": " << w.visible_points << " pts over " << w.visible_extent << ", " << w.planes
         << " planes, normal " << w.normal_error_rad * 180 / 3.141592653589793 << " deg, offset " << w.offset_error
         << ", ends " << w.end_error << ";";
  return text.str();
}

}  // namespace relslam::em::test
