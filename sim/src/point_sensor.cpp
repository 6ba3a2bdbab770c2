#include "relslam/sim/point_sensor.hpp"

#include "checked.hpp"
#include "relslam/sim/random.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace relslam::sim {
namespace {

// Cells along a side of `length`: enough that no cell is wider than `spacing`, at least one.
// The tiny slack keeps an exact multiple (4 / 0.2) from gaining a cell to rounding.
double cells_along(double length, double spacing) { return std::max(1.0, std::ceil(length / spacing - 1e-9)); }

}  // namespace

std::vector<OptionIssue> check(const PointSensorOptions& o) {
  std::vector<OptionIssue> issues;
  for (const OptionIssue& issue : check(o.frustum)) issues.push_back({"frustum." + issue.field, issue.problem});
  for (OptionIssue& issue : check_fields(o)) issues.push_back(std::move(issue));
  return issues;
}

PointField make_point_field(const PlanarWorld& world, double spacing, double jitter, std::uint64_t seed) {
  double total = 0.0;
  for (const Wall& wall : world.walls) total += cells_along(wall.length(), spacing) * cells_along(wall.height, spacing);
  if (!(total <= kMaxFieldPoints))
    throw OptionError("spacing", "gives " + format_number(total) + " field points, more than " +
                                     format_number(kMaxFieldPoints) + "; use a larger spacing");
  PointField field;
  field.points.reserve(static_cast<std::size_t>(total));
  for (std::size_t w = 0; w < world.walls.size(); ++w) {
    const Wall& wall = world.walls[w];
    field.first_point.push_back(field.points.size());
    const int along = static_cast<int>(cells_along(wall.length(), spacing));
    const int up = static_cast<int>(cells_along(wall.height, spacing));
    const double cell_s = wall.length() / along, cell_y = wall.height / up;
    const Eigen::Vector2d u = wall.tangent();
    RandomSequence rng(seed, Stream::WallPointField, static_cast<std::uint64_t>(wall.id));
    for (int i = 0; i < along; ++i)
      for (int j = 0; j < up; ++j) {
        // Two draws per point in a fixed order, so the field is the same bits everywhere.
        const double ds = rng.uniform(-jitter, jitter), dy = rng.uniform(-jitter, jitter);
        const double s = (i + 0.5 + ds) * cell_s, y = (j + 0.5 + dy) * cell_y;
        const Eigen::Vector2d xz = wall.a + s * u;
        field.points.push_back({{xz.x(), y, xz.y()}, static_cast<int>(w)});
      }
  }
  field.first_point.push_back(field.points.size());
  return field;
}

PointSensor::PointSensor(const PointSensorOptions& options, const PlanarWorld& world, std::uint64_t seed)
    : options_(checked(options)),
      world_(checked(world)),
      seed_(seed),
      field_(make_point_field(world_, options_.spacing, options_.jitter, seed)) {}

PointSimFrame PointSensor::observe(const PlanarPose& world_T_robot, int k) const {
  const PointSensorOptions& o = options_;
  const Eigen::Vector2d robot = world_T_robot.translation;
  PointSimFrame out;
  out.observation.iteration = k;
  out.truth.iteration = k;
  out.truth.world_T_robot = world_T_robot;

  // The footprint without its near cut is the cone from the robot: the segment from a visible
  // point to the robot stays inside it, so only walls reaching into it can occlude (whichever
  // way they face), and only walls reaching into the footprint can have visible points.
  ViewingFrustum cone = o.frustum;
  cone.near = 0.0;
  std::vector<const Wall*> occluders;
  std::vector<bool> may_show(world_.walls.size(), false);
  for (std::size_t w = 0; w < world_.walls.size(); ++w) {
    const Wall& wall = world_.walls[w];
    const Eigen::Vector2d a = world_T_robot.inverse_apply(wall.a), b = world_T_robot.inverse_apply(wall.b);
    if (!cone.clip(a, b)) continue;
    if (o.occlusion) occluders.push_back(&wall);
    may_show[w] = wall.visible_from(robot, o.backface_cull) && o.frustum.clip(a, b).has_value();
  }

  for (std::size_t w = 0; w < world_.walls.size(); ++w) {
    if (!may_show[w]) continue;
    const Wall& wall = world_.walls[w];
    for (std::size_t i = field_.first_point[w]; i < field_.first_point[w + 1]; ++i) {
      const Eigen::Vector3d& p = field_.points[i].p_world;
      const Eigen::Vector2d xz(p.x(), p.z());
      const Eigen::Vector2d xz_robot = world_T_robot.inverse_apply(xz);
      if (!o.frustum.contains(xz_robot)) continue;
      const bool hidden = std::any_of(occluders.begin(), occluders.end(), [&](const Wall* other) {
        return other != &wall && segment_crosses_wall(xz, robot, *other);
      });
      if (hidden) continue;
      Eigen::Vector3d p_robot(xz_robot.x(), p.y(), xz_robot.y());
      if (o.sigma > 0.0) {
        RandomSequence rng(seed_, Stream::WallPointNoise, static_cast<std::uint64_t>(k), i);
        const double nx = rng.gaussian(), ny = rng.gaussian(), nz = rng.gaussian();
        p_robot += o.sigma * Eigen::Vector3d(nx, ny, nz);
      }
      out.observation.points.push_back(p_robot);
      out.truth.wall_ids.push_back(wall.id);
    }
  }

  if (o.shuffle) {
    // Shuffled together, from the iteration's own stream.
    RandomSequence rng(seed_, Stream::WallPointShuffle, static_cast<std::uint64_t>(k));
    shuffle_together(rng, out.observation.points, out.truth.wall_ids);
  }
  return out;
}

}  // namespace relslam::sim
