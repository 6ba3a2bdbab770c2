#include "plane_world_fixture.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace relslam::plane::test {
namespace {

// Whether the segment p→q (robot frame) meets the box [near, far] × [−w, w] (Liang–Barsky).
bool segment_meets_box(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Visibility& v) {
  double enter = 0, leave = 1;
  const Eigen::Vector2d d = q - p;
  const double lo[2] = {v.near, -v.half_width}, hi[2] = {v.far, v.half_width};
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] == 0) {
      if (p[axis] < lo[axis] || p[axis] > hi[axis]) return false;
      continue;
    }
    double t0 = (lo[axis] - p[axis]) / d[axis], t1 = (hi[axis] - p[axis]) / d[axis];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  return enter <= leave;
}

}  // namespace

PathBuilder& PathBuilder::move(double distance, double step) {
  const int n = static_cast<int>(std::lround(distance / step));
  for (int i = 0; i < n; ++i) poses_.push_back(poses_.back() * PlanarPose::from(distance / n, 0, 0));
  return *this;
}

PathBuilder& PathBuilder::turn(double angle_rad, double step_rad) {
  const int n = static_cast<int>(std::lround(std::abs(angle_rad) / step_rad));
  for (int i = 0; i < n; ++i) poses_.push_back(poses_.back() * PlanarPose::from(0, 0, angle_rad / n));
  return *this;
}

PlaneFrame observe(const std::vector<Wall>& walls, const PlanarPose& world_T_robot, int iteration,
                   const Visibility& visibility, std::vector<int>* wall_ids) {
  PlaneFrame frame{iteration, {}, nullptr, {}};
  if (wall_ids) wall_ids->clear();
  for (int w = 0; w < static_cast<int>(walls.size()); ++w) {
    PlaneObject plane{world_T_robot.inverse_apply(walls[w].a), world_T_robot.inverse_apply(walls[w].b)};
    plane.iteration = iteration;
    // Back-face culling: the robot (the origin) must be in front of the wall.
    if (plane.offset() <= 0) continue;
    if (!visibility.always && !segment_meets_box(plane.a, plane.b, visibility)) continue;
    frame.planes.push_back(plane);
    if (wall_ids) wall_ids->push_back(w);
  }
  return frame;
}

PlaneRun run_path(const std::vector<Wall>& walls, const std::vector<PlanarPose>& path, const Visibility& visibility) {
  PlaneRun run;
  for (int t = 0; t < static_cast<int>(path.size()); ++t) {
    run.world_T_robot.push_back(path[t]);
    run.wall_ids.emplace_back();
    run.frames.push_back(observe(walls, path[t], t, visibility, &run.wall_ids.back()));
  }
  return run;
}

std::vector<Wall> four_planes_walls() {
  return {{{-4, -5}, {4, -5}}, {{5, -4}, {5, 4}}, {{4, 5}, {-4, 5}}, {{-5, 4}, {-5, -4}}};
}

std::vector<PlanarPose> four_planes_path(int loops, double step, double turn_step_rad) {
  PathBuilder path(PlanarPose::from(-2, -2, 0));
  for (int side = 0; side < 4 * loops; ++side) path.move(4, step).turn(std::numbers::pi / 2, turn_step_rad);
  return path.poses();
}

std::vector<Wall> hallway_walls() {
  std::vector<Wall> walls;
  for (int k = 0; k < 8; ++k) {
    const double lo = 0.5 + 5 * k, hi = lo + 4;
    walls.push_back({{hi, 1.5}, {lo, 1.5}});    // left side, facing −z
    walls.push_back({{lo, -1.5}, {hi, -1.5}});  // right side, facing +z
  }
  walls.push_back({{41, -1.5}, {41, 1.5}});  // end wall, facing −x
  return walls;
}

}  // namespace relslam::plane::test
