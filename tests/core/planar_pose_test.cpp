#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace relslam {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(PlanarPose, WrapAngleKeepsTheHalfOpenInterval) {
  EXPECT_DOUBLE_EQ(wrap_angle(kPi), kPi);
  EXPECT_DOUBLE_EQ(wrap_angle(-kPi), kPi);
  EXPECT_NEAR(wrap_angle(3 * kPi / 2), -kPi / 2, 1e-15);
  EXPECT_NEAR(wrap_angle(-5 * kPi / 2), -kPi / 2, 1e-15);
  EXPECT_DOUBLE_EQ(wrap_angle(0.3), 0.3);
}

TEST(PlanarPose, HeadingNinetyDegreesFacesWorldPlusZ) {
  const PlanarPose robot = PlanarPose::from(1, 2, kPi / 2);
  const Eigen::Vector2d ahead = robot * Eigen::Vector2d(1, 0);  // one unit in front of the robot
  EXPECT_NEAR(ahead.x(), 1, 1e-15);
  EXPECT_NEAR(ahead.y(), 3, 1e-15);
}

TEST(PlanarPose, ComposeInverseAndApplyAgreeOnRandomPoses) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-10, 10), angle(-kPi, kPi);
  for (int i = 0; i < 200; ++i) {
    const PlanarPose a = PlanarPose::from(u(rng), u(rng), angle(rng));
    const PlanarPose b = PlanarPose::from(u(rng), u(rng), angle(rng));
    const Eigen::Vector2d p(u(rng), u(rng));
    EXPECT_LT(((a * b) * p - a * (b * p)).norm(), 1e-12);
    const PlanarPose identity = a * a.inverse();
    EXPECT_LT(identity.translation.norm(), 1e-12);
    EXPECT_NEAR(identity.heading, 0, 1e-12);
    EXPECT_LT((a.inverse_apply(a * p) - p).norm(), 1e-12);
  }
}

TEST(PlanarPose, RigidFromPlanarActsAsThePlanarPoseOnXZ) {
  const PlanarPose pose = PlanarPose::from(3, -1, 0.7);
  const Rigid3 rigid = rigid_from_planar(pose, 1.25);
  const Eigen::Vector2d p(0.4, -2.0);
  const Eigen::Vector3d q = rigid * Eigen::Vector3d(p.x(), 0.5, p.y());
  const Eigen::Vector2d expected = pose * p;
  EXPECT_NEAR(q.x(), expected.x(), 1e-12);
  EXPECT_NEAR(q.y(), 1.75, 1e-12);  // heights only shift
  EXPECT_NEAR(q.z(), expected.y(), 1e-12);
  EXPECT_NEAR(rigid.rotation.determinant(), 1.0, 1e-12);
}

TEST(PlaneObject, NormalPointsToTheFrontAndKeyPointOneHasTheSmallerXAtZeroDegrees) {
  // A wall straight ahead of the robot (x = 5), seen from the front: its normal points back at
  // the robot (−x); turned by −θ it lies along +x, normal +z, with a at the smaller x (Rule 14).
  PlaneObject wall;
  wall.a = {5, -1};
  wall.b = {5, 1};
  EXPECT_LT((wall.normal() - Eigen::Vector2d(-1, 0)).norm(), 1e-15);
  EXPECT_NEAR(wall.offset(), 5, 1e-15);  // the robot is 5 in front of it
  EXPECT_NEAR(wall.angle(), kPi / 2, 1e-15);
  const PlaneObject at_zero = wall.transformed(PlanarPose::from(0, 0, -wall.angle()));
  EXPECT_LT(at_zero.a.x(), at_zero.b.x());
  EXPECT_LT((at_zero.normal() - Eigen::Vector2d(0, 1)).norm(), 1e-15);
}

TEST(PlaneObject, FromPoseRoundTripsPoseAndLength) {
  const PlanarPose p = PlanarPose::from(2, 3, 2.5);
  const PlaneObject plane = PlaneObject::from_pose(p, 4.0, 0.0, 2.5, 17);
  EXPECT_NEAR(plane.length(), 4.0, 1e-12);
  EXPECT_LT((plane.midpoint() - p.translation).norm(), 1e-12);
  EXPECT_NEAR(plane.angle(), 2.5, 1e-12);
  EXPECT_EQ(plane.iteration, 17);
  EXPECT_DOUBLE_EQ(plane.height(), 2.5);
}

}  // namespace
}  // namespace relslam
