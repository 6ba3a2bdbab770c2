#pragma once
// Trajectory error as the TUM benchmark and evo define it: absolute
// trajectory error (ATE) RMSE without and with a rigid Umeyama/Horn alignment, and relative
// pose error (RPE) per frame.

#include "relslam/core/rigid.hpp"

#include <vector>

namespace relslam::eval {

struct TrajectoryError {
  double ate_rmse = 0;              // estimate and truth share a frame by construction: no alignment
  double ate_rmse_aligned = 0;      // after the best rigid motion (SE(3) Umeyama, no scale)
  double rpe_translation_rmse = 0;  // of the frame-to-frame motion, units
  double rpe_rotation_rmse_deg = 0;
};

// Poses paired by index (same iterations). Empty input gives zeros.
TrajectoryError trajectory_error(const std::vector<Rigid3>& estimate, const std::vector<Rigid3>& truth);

}  // namespace relslam::eval
