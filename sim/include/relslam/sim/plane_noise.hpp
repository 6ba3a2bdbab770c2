#pragma once
// Per-plane sensor noise of the planar world: each wall moved by its own small rigid motion
// every iteration (thesis `PlaneObject::GenerateNoisyPosition`; thesis 4.3.3,
// A4). Part of relslam/sim: Eigen only.

#include "relslam/core/option_issue.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <numbers>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace relslam::sim {

enum class PlaneNoiseModel {
  None,
  // Rotation and translation drawn from N(0, σ²) per wall and iteration [R distribution].
  Gaussian,
  // ... from U(−e, e) instead, e given by the same fields [R].
  Uniform,
  // The rotation cycles −e, 0, +e by iteration mod 3 with the same magnitude, the position
  // noise stays Gaussian: the zero-mean-per-short-window noise under which the thesis saw the
  // extra map noise of pairwise intervals disappear (thesis 4.3.3, Figs 74/75) [T].
  ThreeValuedRotation,
};
std::string_view to_string(PlaneNoiseModel model);
std::optional<PlaneNoiseModel> parse_plane_noise_model(std::string_view name);

// The thesis adds noise per plane but gives no magnitudes [T]; the values are ours [R].
struct PlaneNoiseOptions {
  PlaneNoiseModel model = PlaneNoiseModel::Gaussian;  // "with noise" is the default run [R]
  // σ_p (Gaussian) or the half-width e_p (Uniform) of the translation on each axis, units.
  double position = 0.01;
  // σ_r (Gaussian) or e_r (Uniform, three-valued) of the rotation about the wall's midpoint.
  double rotation_rad = 0.3 * std::numbers::pi / 180.0;
  // σ_end: independent Gaussian jitter of each end along the wall, for size-noise studies
  // (Rule 20, Fig. 88); off by default [R].
  double end_sigma = 0.0;

  static PlaneNoiseOptions with_noise() { return {}; }
  // thesis 4.3.3's "small noise": half of each magnitude [R].
  static PlaneNoiseOptions small_noise() {
    return {PlaneNoiseModel::Gaussian, 0.005, 0.15 * std::numbers::pi / 180.0, 0.0};
  }
  static PlaneNoiseOptions none() { return {PlaneNoiseModel::None, 0.0, 0.0, 0.0}; }
};

// Every violated constraint; fields "position", "rotation_deg", "end_sigma".
std::vector<OptionIssue> check(const PlaneNoiseOptions& options);

// One wall's noise at one iteration, in the robot frame.
struct WallNoise {
  double rotation_rad = 0.0;                              // about the whole wall's midpoint
  Eigen::Vector2d translation = Eigen::Vector2d::Zero();  // after the rotation
  double shift_a = 0.0;                                   // along the wall, after the rigid motion
  double shift_b = 0.0;

  // The wall a→b moved by this noise. Zero components are skipped, so zero noise leaves both
  // ends bit for bit unchanged.
  std::pair<Eigen::Vector2d, Eigen::Vector2d> apply(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;
};

// The noise of wall `wall_id` at iteration k: a pure function of (options, seed, wall, k), so
// frames can be made in any order and a wall's noise does not depend on which other walls are
// in view (streams PlanePose and PlaneEnds, random.hpp).
WallNoise draw_wall_noise(const PlaneNoiseOptions& options, std::uint64_t seed, int wall_id, int k);

}  // namespace relslam::sim
