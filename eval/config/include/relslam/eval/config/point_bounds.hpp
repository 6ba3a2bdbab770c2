#pragma once
// The adaptive preset's matching bounds: Relative Point's local, compensated, global
// and merge bounds and RltBinning's gaps scaled from the sensor noise (libslam's
// noise_bounds.hpp), unless the file or --set gives them. Where each came from goes to
// manifest.json ("derived").

#include "relslam/eval/config/scenario.hpp"

#include <functional>
#include <string>

namespace relslam::eval {

// Per-axis noise at the sensor's far range, and what it was read from.
struct NoiseModel {
  double sigma = 0;
  std::string source;
};

// The simulator's: sigma·(1 + range/far) with range_noise, largest at the far range.
NoiseModel simulated_noise(const sim::SimOptions& sim);

// Sets the bounds of `scenario.relative_point` from `noise` when its preset is adaptive.
// `given(key)`: the key was set explicitly (file, --set), so it stays as given.
void derive_point_bounds(Scenario& scenario, const NoiseModel& noise,
                         const std::function<bool(const std::string&)>& given);

}  // namespace relslam::eval

namespace relslam::eval {

// The Relative Plane adaptive preset's integrity bounds scaled from the planar sensor's noise
// (relative_plane.integrity.offset_bound = 0.05 + 6 sigma, angle_bound_deg = 1.5 + 6 sigma_r,
// sigma_r for the point sensor taken as 40 sigma_pt degrees [C]), unless given; recorded in
// "derived" like the point bounds. Relocalisation (integrity.recovery) and the pose from real
// ends (integrity.real_ends) are off unless given.
void derive_plane_bounds(Scenario& scenario, const std::function<bool(const std::string&)>& given);

}  // namespace relslam::eval
