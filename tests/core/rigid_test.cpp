#include "relslam/core/rigid.hpp"

#include <gtest/gtest.h>

namespace relslam {
namespace {

Rigid3 sample_pose() { return {rotation_about(Eigen::Vector3d(1, 2, 3).normalized(), 0.7), Eigen::Vector3d(4, -5, 6)}; }

TEST(Rigid3, InverseComposesToIdentity) {
  const Rigid3 a_T_b = sample_pose();
  const Rigid3 id = a_T_b * a_T_b.inverse();
  EXPECT_TRUE(id.rotation.isApprox(Eigen::Matrix3d::Identity(), 1e-14));
  EXPECT_LT(id.translation.norm(), 1e-14);
}

TEST(Rigid3, CompositionAppliesInnerTransformFirst) {
  const Rigid3 a_T_b = sample_pose();
  const Rigid3 b_T_c{rotation_about(Eigen::Vector3d::UnitY(), -1.2), Eigen::Vector3d(0.5, 0, 2)};
  const Eigen::Vector3d p_c(1, 2, 3);
  EXPECT_TRUE(((a_T_b * b_T_c) * p_c).isApprox(a_T_b * (b_T_c * p_c), 1e-14));
  EXPECT_TRUE(a_T_b.inverse_apply(a_T_b * p_c).isApprox(p_c, 1e-14));
}

TEST(Rigid3, QuaternionHasNonNegativeScalarPart) {
  // A rotation by 350° about z has a natural quaternion with w < 0; we always report w >= 0.
  const Rigid3 pose{rotation_about(Eigen::Vector3d::UnitZ(), 350.0 * M_PI / 180.0), Eigen::Vector3d::Zero()};
  const Eigen::Quaterniond q = pose.quaternion();
  EXPECT_GE(q.w(), 0.0);
  EXPECT_TRUE(q.toRotationMatrix().isApprox(pose.rotation, 1e-14));
}

}  // namespace
}  // namespace relslam
