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

// Deviation (adaptive preset): two matched pairs fix b_T_a up to a rotation about
// their line. That one freedom comes from `prior_b_R_a`: the result's rotation is the one
// closest to the prior (smallest angle between them) that maps a's line onto b's, i.e. the
// prior followed by the shortest rotation turning the prior's image of a's line onto b's line;
// the translation maps the pairs' midpoints onto each other. A robot on a floor turns about its
// up axis (`b_up`, a unit vector in b's frame), so a prior from an earlier pose is wrong mostly
// in yaw, and a yaw error reaches the result only by the sine of b's line's elevation above the
// floor (exactly none for a level line): nothing when that sine exceeds `max_line_sine` (a steep
// line), or when either pair is (nearly) coincident.
std::optional<Rigid3> register_two_points(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1,
                                          const Eigen::Vector3d& b0, const Eigen::Vector3d& b1,
                                          const Eigen::Matrix3d& prior_b_R_a, const Eigen::Vector3d& b_up,
                                          double max_line_sine);

// Deviation (adaptive preset): b_T_a from one pair, a0 ↦ b0, with the rotation given
// (one point fixes only the translation).
Rigid3 register_one_point(const Eigen::Vector3d& a0, const Eigen::Vector3d& b0, const Eigen::Matrix3d& b_R_a);

// Deviation (adaptive preset): b_T_a from matched pairs with the rotation given: the
// translation maps the pairs' centroid a onto b's (register_one_point of the centroids). A swap
// of two pairs leaves it where it was.
Rigid3 register_centroids(std::span<const Eigen::Vector3d> a, std::span<const Eigen::Vector3d> b,
                          const Eigen::Matrix3d& b_R_a);

// Deviation (adaptive preset): the rotation `weight` of the way from `from` to `to`
// (spherical interpolation; 0: from, 1: to).
Eigen::Matrix3d interpolate_rotation(const Eigen::Matrix3d& from, const Eigen::Matrix3d& to, double weight);

// Deviation (adaptive preset): the rotation closest (Frobenius) to `sum`, a sum of
// rotations: their chordal mean. Many noisy estimates of one rotation average to it.
Eigen::Matrix3d mean_rotation(const Eigen::Matrix3d& sum);

}  // namespace relslam::point
