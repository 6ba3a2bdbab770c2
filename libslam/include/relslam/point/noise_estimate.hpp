#pragma once
// The sensor noise of data that states none, estimated from the residuals of the group averages
// (beyond the thesis), so that noise_bounds.hpp can scale the bounds from it. Eigen only.

#include "relslam/point/options.hpp"
#include "relslam/point/rlt_group.hpp"
#include "relslam/point/rlt_point.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace relslam::point {

class RltMapper;

struct NoiseEstimate {
  double sigma = 0;   // per axis, units
  int pairs = 0;      // member pairs it rests on
  int groups = 0;     // groups they belong to
  int pilot_runs = 0;  // runs estimate_noise_online made (0: estimate_noise_sigma alone)
};

// Per-axis noise from the residuals of the group averages: in each group computed on at least a
// few iterations, the distance between two consecutive members varies about its average over
// the group's iterations only by the noise of the two observations, sigma·sqrt(2) for isotropic
// noise. A distance is rigid-invariant, so neither the robot's motion nor the basis frame's own
// noise enters (a member's position in the basis frame spreads wider than sigma, with its lever
// arm to the basis). The median over pairs ignores dynamic points and wrong matches; pairs
// closer than a few of their own spreads (where a distance's noise is no longer Gaussian) are
// left out. nullopt without such a pair.
std::optional<NoiseEstimate> estimate_noise_sigma(const std::vector<RltPoint>& points,
                                                  const std::vector<RltGroup>& groups);

// Pilot runs of the online estimate at most. The first runs with `options`' bounds (the
// thesis's), which cut off the larger deviations of noisier data (sigma 0.3 came out 21 % low,
// from 3 groups); each next one with the bounds scaled from the estimate before [C].
inline constexpr int kNoisePilotRuns = 3;
// Two pilot runs' estimates this close (relative) are taken as settled [C].
inline constexpr double kNoiseSettled = 0.1;

// The estimate as a run without a noise model makes it: `feed` steps a fresh RltMapper (built
// from `options`, without relaxation) over the data's first iterations, estimate_noise_sigma
// reads its groups; above the thesis's noise the pilot is repeated with the bounds scaled from
// the estimate until two agree within kNoiseSettled (at most kNoisePilotRuns runs).
std::optional<NoiseEstimate> estimate_noise_online(const PointSlamOptions& options,
                                                   const std::function<void(RltMapper&)>& feed);

}  // namespace relslam::point
