#pragma once
// Deviation (adaptive preset): one rotation read off a run of noisy rotations of a
// steadily turning frame, by a straight-line fit of their rotation vectors. Eigen only.

#include <Eigen/Core>

#include <optional>
#include <span>
#include <utility>

namespace relslam::point {

// A frame turning at a constant rate (the figure eight's arcs: a constant angle per iteration;
// a straight: none) has R(t) = R(t0) * exp(w * (t - t0)): relative to any one of them, the
// rotation vectors log(R(t_ref)^T R(t)) lie on a straight line in t. Given rotations observed at
// iterations t (each with a whole observation's noise), the rotation at `at` from the least-
// squares line through their rotation vectors (relative to the first one): with n rotations its
// noise is about 2/sqrt(n) of one rotation's at the run's end, against the one rotation itself.
// Nothing for fewer than three distinct iterations.
std::optional<Eigen::Matrix3d> fitted_rotation(std::span<const std::pair<int, Eigen::Matrix3d>> rotations, int at);

}  // namespace relslam::point
