#pragma once
// RltICP (thesis 6.3.2): closed-form registration of matched point pairs. Eigen only.

#include "relslam/core/rigid.hpp"

#include <optional>
#include <span>

namespace relslam::point {

// The rigid motion b_T_a minimising sum |b_i - b_T_a * a_i|^2 over pairs already matched
// (Arun, Huang, Blostein 1987; the one-pass ICP step of [BeMc92] the thesis uses): remove the
// means, SVD of the cross-covariance, rotation with the reflection fix, translation from the
// rotated mean difference. Planar sets (all z = 0, as in Victoria Park) are handled; returns
// nothing for fewer than 3 pairs or (near-)collinear points, whose rotation about their line
// is undetermined.
// Spans, so callers can pass scratch buffers they keep between iterations.
std::optional<Rigid3> rlt_icp(std::span<const Eigen::Vector3d> a, std::span<const Eigen::Vector3d> b);

}  // namespace relslam::point
