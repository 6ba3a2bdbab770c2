#pragma once
// Wheel odometry for the range sensors' runs (laser_sensor.hpp, depth_camera.hpp): the true
// motion between two frames with seeded Gaussian errors that grow with it, so dead reckoning
// drifts as a real robot's does (the thesis's algorithms use no odometry; the scan-matching
// baseline and the dead-reckoning row do). Part of relslam/sim: Eigen only.

#include "relslam/core/option_fields.hpp"
#include "relslam/core/option_issue.hpp"
#include "relslam/core/planar_pose.hpp"

#include <cstdint>
#include <numbers>

namespace relslam::sim {

struct OdometryNoiseOptions {
  // σ of each translation axis, as a share of the distance moved [C].
  double translation_ratio = 0.05;
  // σ of the heading change: a share of the turn plus a drift per unit moved [C: ~1°/m, the order
  // of SENA's odometry's loop gap of 17° over its ~70 m].
  double heading_ratio = 0.05;
  double heading_drift_rad = 1.0 * std::numbers::pi / 180.0;
};

void describe(OptionsOf<OdometryNoiseOptions> auto& o, auto& f) {
  f.field("translation_ratio", o.translation_ratio, "odometry: translation sigma per axis, share of the distance",
          at_least(0.0), at_most(10.0));
  f.field("heading_ratio", o.heading_ratio, "odometry: heading sigma, share of the turn", at_least(0.0),
          at_most(10.0));
  f.degrees("heading_drift_deg", o.heading_drift_rad, "odometry: heading sigma per unit moved, degrees",
            at_least(0.0), at_most(90.0));
}

// The odometry reading of the true motion previous_T_current between frames k − 1 and k: a pure
// function of (increment, options, seed, k); all ratios 0 give the increment itself.
PlanarPose noisy_odometry(const PlanarPose& increment, const OdometryNoiseOptions& options, std::uint64_t seed, int k);

}  // namespace relslam::sim
