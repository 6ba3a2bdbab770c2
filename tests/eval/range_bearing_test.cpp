#include "relslam/eval/io/range_bearing.hpp"

#include "relslam/sim/random.hpp"

#include <gtest/gtest.h>
#include <mrpt/poses/CPose3D.h>
#include <Eigen/Dense>

namespace relslam::eval {
namespace {

TEST(RangeBearing, RobotForwardIsMrptXAndTheMappingIsARotation) {
  EXPECT_EQ(mrpt_from_robot({0, 0, 1}), Eigen::Vector3d(1, 0, 0)) << "forward";
  EXPECT_EQ(mrpt_from_robot({1, 0, 0}), Eigen::Vector3d(0, 1, 0)) << "left";
  EXPECT_EQ(mrpt_from_robot({0, 1, 0}), Eigen::Vector3d(0, 0, 1)) << "up";
  Eigen::Matrix3d m;
  m << mrpt_from_robot(Eigen::Vector3d::UnitX()), mrpt_from_robot(Eigen::Vector3d::UnitY()),
      mrpt_from_robot(Eigen::Vector3d::UnitZ());
  EXPECT_DOUBLE_EQ(m.determinant(), 1.0);
  EXPECT_EQ(robot_from_mrpt(mrpt_from_robot({1, 2, 3})), Eigen::Vector3d(1, 2, 3));
}

TEST(RangeBearing, MatchesMrptSphericalCoordinates) {
  sim::RandomSequence rng(21, sim::Stream::Field);
  const mrpt::poses::CPose3D sensor;  // at the origin
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Vector3d p(rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-50, 50));
    double range = 0, yaw = 0, pitch = 0;
    sensor.sphericalCoordinates(mrpt::math::TPoint3D(p.x(), p.y(), p.z()), range, yaw, pitch);
    const RangeBearing m = range_bearing_of(p);
    EXPECT_NEAR(m.range, range, 1e-12);
    EXPECT_NEAR(m.yaw_rad, yaw, 1e-12);
    EXPECT_NEAR(m.pitch_rad, pitch, 1e-12);
  }
}

TEST(RangeBearing, PointOfInvertsRangeBearingOf) {
  sim::RandomSequence rng(22, sim::Stream::Field);
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Vector3d p(rng.uniform(-100, 100), rng.uniform(-100, 100), rng.uniform(-100, 100));
    EXPECT_LT((point_of(range_bearing_of(p)) - p).norm(), 1e-12 * p.norm());
  }
  EXPECT_EQ(point_of(range_bearing_of(Eigen::Vector3d::Zero())), Eigen::Vector3d::Zero());
  // Pitch is negative elevation: a point above the sensor has negative pitch.
  EXPECT_LT(range_bearing_of({10, 0, 5}).pitch_rad, 0);
}

}  // namespace
}  // namespace relslam::eval
