#include "relslam/sim/laser_sensor.hpp"

#include "checked.hpp"
#include "relslam/sim/random.hpp"
#include "relslam/sim/ray_cast.hpp"

#include <algorithm>
#include <cmath>

namespace relslam::sim {

std::vector<OptionIssue> check(const LaserSensorOptions& options) { return check_fields(options); }

LaserSensor::LaserSensor(const LaserSensorOptions& options) : options_(checked(options)) {}

LaserSimFrame LaserSensor::scan(const PlanarWorld& world, const PlanarPose& world_T_robot, std::uint64_t seed,
                                int k) const {
  const LaserSensorOptions& o = options_;
  LaserSimFrame out;
  LaserScan& scan = out.scan;
  scan.robot_T_sensor = o.robot_T_sensor;
  scan.start_bearing_rad = -0.5 * o.aperture_rad;
  scan.bearing_step_rad = o.aperture_rad / (o.rays - 1);
  scan.max_range = o.max_range;
  const auto n = static_cast<std::size_t>(o.rays);
  scan.ranges.assign(n, 0.0f);
  scan.valid.assign(n, 0);
  out.wall.assign(n, -1);

  const PlanarPose world_T_sensor = world_T_robot * o.robot_T_sensor;
  RandomSequence noise(seed, Stream::LaserRange, static_cast<std::uint64_t>(k));
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = world_T_sensor.heading + scan.bearing(i);
    const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
    // One draw per ray whether or not it returns, so a wall moved out of sight leaves every
    // other ray's noise unchanged.
    const double error = o.range_sigma * noise.gaussian();
    const std::optional<RayHit> hit = first_ray_hit(world, world_T_sensor.translation, direction, o.max_range);
    if (!hit) continue;
    const double range = std::clamp(hit->distance + error, 1e-6, o.max_range);
    scan.ranges[i] = static_cast<float>(range);
    scan.valid[i] = 1;
    out.wall[i] = hit->wall;
  }
  return out;
}

}  // namespace relslam::sim
