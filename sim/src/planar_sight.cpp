// What the map-file reader checks along a planar path before a run: that two walls are seen at
// once, and that the path does not run through a wall. Both must cost time in proportion to the
// map, not to the path: a 12 KB map asked for a 10-million-step path and took 107 s to refuse.

#include "relslam/sim/planar_sight.hpp"

#include "relslam/sim/plane_sensor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace relslam::sim {
namespace {

struct Box {
  Eigen::Vector2d low = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d high = -low;
  void add(const Eigen::Vector2d& p) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
};

// Positions of iterations first..last (both included).
Box box_of(const PlanarPath& path, int first, int last) {
  Box box;
  for (int k = first; k <= last; ++k) box.add(path.world_T_robot(k).translation);
  return box;
}

double distance_to_segment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (a + t * d - p).norm();
}

// Whether the segment a→b comes within `reach` of the box: it crosses the box grown by `reach`
// (a slab test), which covers every point within reach and a little more at the corners.
bool near_box(const Box& box, const Eigen::Vector2d& a, const Eigen::Vector2d& b, double reach) {
  const Eigen::Vector2d low = box.low.array() - reach, high = box.high.array() + reach;
  double enter = 0.0, exit = 1.0;
  for (int axis = 0; axis < 2; ++axis) {
    const double d = b[axis] - a[axis];
    if (d == 0.0) {
      if (a[axis] < low[axis] || a[axis] > high[axis]) return false;
      continue;
    }
    double t0 = (low[axis] - a[axis]) / d, t1 = (high[axis] - a[axis]) / d;
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    exit = std::min(exit, t1);
    if (enter > exit) return false;
  }
  return true;
}

// The farthest a seen part of a wall can be from the robot: the frustum's far corners; without
// a frustum (always visible, scripted) any distance.
double sensor_reach(const PlaneSensorOptions& sensor) {
  if (sensor.mode != PlaneVisibility::Frustum && sensor.mode != PlaneVisibility::FullSize)
    return std::numeric_limits<double>::infinity();
  return sensor.frustum.far / std::cos(sensor.frustum.half_angle_rad) * (1.0 + 1e-9) + 1e-9;
}

// Walls with a point within `reach` of some position in `box`.
std::vector<Wall> walls_near(const PlanarWorld& world, const Box& box, double reach) {
  std::vector<Wall> near;
  for (const Wall& wall : world.walls)
    if (std::isinf(reach) || near_box(box, wall.a, wall.b, reach)) near.push_back(wall);
  return near;
}

// Iteration k of one operation: a sensor frame is made only when `count` walls could be seen.
struct SightScan {
  const PlaneSensor& sensor;
  double reach;
  int count;
  long long work = 0;

  bool sees(const PlanarWorld& near, const PlanarPose& pose, int k) {
    int possible = 0;
    for (const Wall& wall : near.walls)
      possible += wall.visible_from(pose.translation, sensor.options().backface_cull) &&
                  distance_to_segment(pose.translation, wall.a, wall.b) <= reach;
    work += static_cast<long long>(near.walls.size());
    if (possible < count) return false;
    work += kSightFrameWork * static_cast<long long>(near.walls.size());
    return static_cast<int>(sensor.observe(near, pose, k).observation.planes.size()) >= count;
  }
};

// A strict crossing: p and q on opposite sides of the wall's line and the wall's ends on
// opposite sides of p→q. Touching or running along a wall is clearance, not a crossing.
std::optional<Eigen::Vector2d> crossing(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Wall& wall) {
  const auto orientation = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
    const Eigen::Vector2d u = b - a, v = c - a;
    return u.x() * v.y() - u.y() * v.x();
  };
  const double side_p = orientation(wall.a, wall.b, p), side_q = orientation(wall.a, wall.b, q);
  if (!(side_p * side_q < 0.0)) return std::nullopt;
  if (!(orientation(p, q, wall.a) * orientation(p, q, wall.b) < 0.0)) return std::nullopt;
  return p + side_p / (side_p - side_q) * (q - p);
}

OptionError too_much_work(const std::string& searched, int count) {
  return OptionError("path", searched + " sees " + std::to_string(count) +
                                 " walls at once, and searching the rest of the path would exceed the limit of " +
                                 std::to_string(kMaxSightWork) + " wall tests: shorten the path");
}

}  // namespace

OperationPlace operation_place(const PathProgram& program, int index) {
  const long long looped = static_cast<long long>(program.loops) * static_cast<long long>(program.steps.size());
  if (index < looped) {
    const std::size_t i = static_cast<std::size_t>(index) % program.steps.size();
    return {&program.steps[i], "steps[" + std::to_string(i) + "]",
            static_cast<int>(index / static_cast<long long>(program.steps.size())) + 1};
  }
  const std::size_t i = static_cast<std::size_t>(index - looped);
  return {&program.then.at(i), "then[" + std::to_string(i) + "]", 0};
}

std::optional<int> first_iteration_seeing(const PlanarMap& map, int count) {
  return first_iteration_seeing(map, PlanarPath(map.path), count);
}

std::optional<int> first_iteration_seeing(const PlanarMap& map, const PlanarPath& path, int count) {
  PlaneSensorOptions exact = map.sensor;
  exact.noise = PlaneNoiseOptions::none();
  const PlaneSensor sensor(exact, 0);
  SightScan scan{sensor, sensor_reach(exact), count};
  int first = 0;  // an operation's iterations: from the pose it starts at to the one it ends at
  for (const int last : path.operation_ends()) {
    const PlanarWorld near{walls_near(map.world, box_of(path, first, last), scan.reach)};
    scan.work += static_cast<long long>(map.world.walls.size()) + (last - first);
    for (int k = first; k <= last && static_cast<int>(near.walls.size()) >= count; ++k) {
      if (scan.sees(near, path.world_T_robot(k), k)) return k;
      if (scan.work > kMaxSightWork) throw too_much_work("no iteration up to " + std::to_string(k), count);
    }
    if (scan.work > kMaxSightWork) throw too_much_work("no iteration up to " + std::to_string(last), count);
    first = last;
  }
  return std::nullopt;
}

std::optional<WallCrossing> first_wall_crossing(const PlanarMap& map, const PlanarPath& path) {
  long long work = 0;
  int first = 0;
  const std::vector<int>& ends = path.operation_ends();
  for (std::size_t op = 0; op < ends.size(); ++op) {
    const int last = ends[op];
    const PathOperation& operation = *operation_place(map.path, static_cast<int>(op)).operation;
    // A MOVE's poses lie on one segment; an ARC's steps are tested against the walls near it.
    const int stride = operation.kind == PathOperationKind::Move ? last - first : 1;
    const std::vector<Wall> near = operation.kind == PathOperationKind::Turn
                                       ? std::vector<Wall>{}
                                       : walls_near(map.world, box_of(path, first, last), 0.0);
    work += static_cast<long long>(map.world.walls.size()) + (last - first) * static_cast<long long>(near.size());
    if (work > kMaxSightWork)
      throw OptionError("path", "checking that the path stays clear of the walls up to iteration " +
                                    std::to_string(last) + " would exceed the limit of " +
                                    std::to_string(kMaxSightWork) + " wall tests: shorten the path");
    for (int k = first; k < last && !near.empty(); k += stride)
      for (std::size_t w = 0; w < near.size(); ++w)
        if (const auto at = crossing(path.world_T_robot(k).translation,
                                     path.world_T_robot(std::min(k + stride, last)).translation, near[w])) {
          // The crossing of a MOVE lies between the two poses either side of it.
          const Eigen::Vector2d from = path.world_T_robot(first).translation;
          const double along = (*at - from).norm();
          const int before = stride == 1 ? k : std::min(last - 1, first + static_cast<int>(along / map.path.speed));
          return WallCrossing{static_cast<int>(op), near[w].id, before, *at};
        }
    first = last;
  }
  return std::nullopt;
}

std::optional<MapExit> first_exit_from_map(const PlanarMap& map, const PlanarPath& path) {
  Box walls;
  for (const Wall& w : map.world.walls) walls.add(w.a), walls.add(w.b);
  // Out of the map is beyond the sensor's reach of every wall's extent: from there nothing the
  // map describes can be seen (a robot may start outside a lone wall it walks up to).
  const double reach = sensor_reach(map.sensor);
  if (!std::isfinite(reach)) return std::nullopt;
  walls.low.array() -= reach;
  walls.high.array() += reach;
  const auto outside = [&](const Eigen::Vector2d& p) {
    return (p.array() < walls.low.array()).any() || (p.array() > walls.high.array()).any();
  };
  int first = 0;
  const std::vector<int>& ends = path.operation_ends();
  for (std::size_t op = 0; op < ends.size(); ++op) {
    const int last = ends[op];
    // A MOVE's poses lie between its ends, and the box is convex: its ends tell.
    const bool move = operation_place(map.path, static_cast<int>(op)).operation->kind == PathOperationKind::Move;
    for (int k = first; k <= last; k += move ? std::max(1, last - first) : 1)
      if (const Eigen::Vector2d p = path.world_T_robot(k).translation; outside(p))
        return MapExit{static_cast<int>(op), k, p, walls.low, walls.high};
    first = last;
  }
  return std::nullopt;
}

}  // namespace relslam::sim
