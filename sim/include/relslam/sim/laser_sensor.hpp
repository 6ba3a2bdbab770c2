#pragma once
// A simulated planar laser scanner over the planar world: the walls the Relative Plane half maps
// (thesis Chapter 4), seen as a real indoor robot sees them, by a 2-D laser (the thesis only
// simulated planes). Ranges come from the ray caster (ray_cast.hpp) with seeded Gaussian range
// noise. The defaults are the scanner of MRPT's SENA log (2006-01ENE-21-SENA_Telecom
// Faculty_one_loop_only.rawlog: 361 rays over 180°, right to left, maximum range 80 m, stated
// range error 0.01 m). Part of relslam/sim: Eigen only.

#include "relslam/core/laser_scan.hpp"
#include "relslam/core/option_fields.hpp"
#include "relslam/core/option_issue.hpp"
#include "relslam/core/planar_pose.hpp"
#include "relslam/sim/planar_world.hpp"

#include <cstdint>
#include <numbers>
#include <vector>

namespace relslam::sim {

// Tags: [C] chosen here; values marked SENA are read from MRPT's SENA log.
struct LaserSensorOptions {
  int rays = 361;                              // rays per scan, evenly spaced over the aperture [C SENA]
  double aperture_rad = std::numbers::pi;      // first to last ray, centred on the sensor's +x [C SENA]
  double max_range = 80.0;                     // beyond it a ray has no return, map units [C SENA]
  double range_sigma = 0.01;                   // Gaussian range noise per ray, map units (0: none) [C SENA]
  // Where the scanner sits on the robot. At the robot's origin, so a scan matcher's pose is the
  // robot's (SENA's scanner sits 0.78 m ahead of it) [C].
  PlanarPose robot_T_sensor;
};

void describe(OptionsOf<LaserSensorOptions> auto& o, auto& f) {
  f.field("rays", o.rays, "rays per scan, evenly spread over the aperture", at_least(2), at_most(100000));
  f.degrees("aperture_deg", o.aperture_rad, "angle from the first ray to the last, degrees", above(0.0),
            at_most(360.0));
  f.field("max_range", o.max_range, "farthest return, map units; beyond it a ray has none", above(0.0),
          at_most(1e6));
  f.field("range_sigma", o.range_sigma, "Gaussian range noise per ray, map units (0: none)", at_least(0.0),
          at_most(10.0));
}

std::vector<OptionIssue> check(const LaserSensorOptions& options);

// One simulated scan and its truth: the wall (position in PlanarWorld::walls) each ray hit, -1
// where it has no return.
struct LaserSimFrame {
  LaserScan scan;
  std::vector<int> wall;
};

class LaserSensor {
 public:
  // Throws OptionError when the options fail check().
  explicit LaserSensor(const LaserSensorOptions& options);
  const LaserSensorOptions& options() const { return options_; }

  // The scan at iteration k from world_T_robot: a pure function of (world, options, seed, k).
  // A noisy range stays within (0, max_range]; a ray whose wall lies beyond max_range has no return.
  LaserSimFrame scan(const PlanarWorld& world, const PlanarPose& world_T_robot, std::uint64_t seed, int k) const;

 private:
  LaserSensorOptions options_;
};

}  // namespace relslam::sim
