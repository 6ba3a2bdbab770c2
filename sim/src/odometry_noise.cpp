#include "relslam/sim/odometry_noise.hpp"

#include "relslam/sim/random.hpp"

#include <cmath>

namespace relslam::sim {

PlanarPose noisy_odometry(const PlanarPose& increment, const OdometryNoiseOptions& o, std::uint64_t seed, int k) {
  RandomSequence rng(seed, Stream::Odometry, static_cast<std::uint64_t>(k));
  const double distance = increment.translation.norm();
  const double sigma_t = o.translation_ratio * distance;
  const double sigma_h = o.heading_ratio * std::abs(increment.heading) + o.heading_drift_rad * distance;
  const double ex = rng.gaussian(), ez = rng.gaussian(), eh = rng.gaussian();
  return PlanarPose::from(increment.translation.x() + sigma_t * ex, increment.translation.y() + sigma_t * ez,
                          increment.heading + sigma_h * eh);
}

}  // namespace relslam::sim
