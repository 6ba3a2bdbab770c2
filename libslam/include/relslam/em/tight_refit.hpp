#pragma once
// The final refit of an extraction's planes on their own points (the M-step of thesis 3.5.2
// step 7 once more, on the inliers of a tight residual gate). Eigen only.
//
// Why: the membership test accepts any point within d_in of a plane and inside its widened box,
// so where two walls meet, the neighbour's points near the corner join the plane and tilt its
// TLS fit (the thesis's Fig. 60 effect, at a corner). The plane's own points lie at the sensor
// noise from it, the neighbour's up to d_in away: a gate at a few robust deviations of the
// residuals separates them, and on noise-free points the refit is exact.

#include "relslam/em/em_plane.hpp"
#include "relslam/em/options.hpp"

#include <span>
#include <vector>

namespace relslam::em {

// For each plane, up to options.refit_rounds times: the plane of its better half (the points
// within the median residual) and the robust deviation of all points' residuals from it,
// σ̂ = 1.4826 · median |n·p + d|; points beyond max(refit_gate · σ̂, 1e-6 · d_in) leave the
// plane, which is fit again; it stops once no point leaves. A plane whose kept points would
// have no plane of their own (fewer than 3, collinear) keeps its points. Off when refit_gate is
// 0. Returns the points removed in all.
int tight_refit(std::vector<EmPlane>& planes, std::span<const Eigen::Vector3d> points, const EmOptions& options);

}  // namespace relslam::em
