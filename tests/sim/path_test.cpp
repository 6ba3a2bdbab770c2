#include "relslam/sim/path.hpp"

#include <gtest/gtest.h>
#include <Eigen/Dense>

namespace relslam::sim {
namespace {

void expect_rotation(const Eigen::Matrix3d& r, const std::string& where) {
  EXPECT_TRUE((r.transpose() * r).isApprox(Eigen::Matrix3d::Identity(), 1e-12)) << where;
  EXPECT_NEAR(r.determinant(), 1.0, 1e-12) << where;
}

TEST(Path, StartPoseIsExactlyTheIdentity) {
  for (PathKind kind : {PathKind::FigureEight, PathKind::Line, PathKind::Stationary}) {
    SimOptions o;
    o.path = kind;
    o.wobble = true;
    const Rigid3 pose = Path(o).world_T_robot(0);
    EXPECT_EQ(pose.rotation, Eigen::Matrix3d::Identity()) << to_string(kind);
    EXPECT_EQ(pose.translation, Eigen::Vector3d::Zero()) << to_string(kind);
  }
}

TEST(Path, FigureEightRunsLoopsTimesIterationsPerLoopAndCloses) {
  SimOptions o;
  o.loops = 3;
  const Path path(o);
  EXPECT_EQ(path.iterations(), 3 * 3800);
  EXPECT_NEAR(path.step_length(), 1145.0 / 3800.0, 1e-15);
  for (int loop = 1; loop <= 3; ++loop) {
    const Rigid3 back = path.world_T_robot(loop * 3800);
    EXPECT_LT(back.translation.norm(), 1e-9) << "loop " << loop;
    EXPECT_TRUE(back.rotation.isApprox(Eigen::Matrix3d::Identity(), 1e-9)) << "loop " << loop;
  }
}

TEST(Path, RobotPassesAboveItsStartAfterTheFirstLobe) {
  const Path path(SimOptions{});
  const Rigid3 half = path.world_T_robot(1900);
  EXPECT_NEAR(half.translation.x(), 0.0, 1e-9);
  EXPECT_NEAR(half.translation.z(), 0.0, 1e-9);
  EXPECT_NEAR(half.translation.y(), 20.0, 1e-9);
}

TEST(Path, IterationsOverrideLoops) {
  SimOptions o;
  o.loops = 5;
  o.iterations = 123;
  EXPECT_EQ(Path(o).iterations(), 123);
}

TEST(Path, DoubleScaleDoublesLengthAndIterations) {
  SimOptions o;
  o.scale = 2.0;
  const Path path(o);
  EXPECT_EQ(path.iterations(), 7600);
  EXPECT_NEAR(path.field_length(), 2290.0, 1e-9);
  EXPECT_NEAR(path.step_length(), 1145.0 / 3800.0, 1e-15) << "same speed";
  EXPECT_NEAR(path.world_T_robot(3800).translation.y(), 40.0, 1e-9) << "incline scales with the path";
}

TEST(Path, RobotFollowsTheTangentWithoutRoll) {
  const Path path(SimOptions{});
  for (int k = 1; k < 3800; k += 97) {
    const Rigid3 pose = path.world_T_robot(k);
    expect_rotation(pose.rotation, "k = " + std::to_string(k));
    const Eigen::Vector3d forward = pose.rotation.col(2), left = pose.rotation.col(0);
    const Eigen::Vector3d travel =
        (path.world_T_robot(k + 1).translation - path.world_T_robot(k - 1).translation).normalized();
    EXPECT_GT(forward.dot(travel), 0.9999) << "k = " << k;
    EXPECT_NEAR(left.y(), 0.0, 1e-12) << "no roll: the left axis stays horizontal";
  }
}

TEST(Path, WobbleRollsThePoseButKeepsItARotation) {
  SimOptions o;
  o.wobble = true;
  const Path path(o);
  double max_left_y = 0;
  for (int k = 0; k < 3800; k += 13) {
    const Rigid3 pose = path.world_T_robot(k);
    expect_rotation(pose.rotation, "k = " + std::to_string(k));
    max_left_y = std::max(max_left_y, std::abs(pose.rotation(1, 0)));
  }
  EXPECT_GT(max_left_y, std::sin(1.5 * M_PI / 180.0)) << "roll of ~2° shows in the left axis";
}

TEST(Path, StepAndFieldLengthAreTheOnesTheOptionsGive) {
  SimOptions o;
  o.iterations = 500;
  for (PathKind kind : {PathKind::FigureEight, PathKind::Line, PathKind::Stationary}) {
    o.path = kind;
    const Path path(o);
    EXPECT_EQ(path.step_length(), step_length(o)) << to_string(kind);
    EXPECT_EQ(path.field_length(), field_length(o)) << to_string(kind);
  }
}

TEST(Path, LineGoesStraightAheadAndStationaryStays) {
  SimOptions o;
  o.path = PathKind::Line;
  o.iterations = 3800;
  const Path line(o);
  const Rigid3 end = line.world_T_robot(3799);
  EXPECT_TRUE(end.rotation.isApprox(Eigen::Matrix3d::Identity(), 1e-15));
  EXPECT_NEAR(end.translation.z(), 3799 * 1145.0 / 3800.0, 1e-9);
  EXPECT_NEAR(line.field_length(), 1145.0 + 110.0, 1e-9);

  o.path = PathKind::Stationary;
  o.iterations = 4000;
  const Path still(o);
  EXPECT_EQ(still.iterations(), 4000);
  EXPECT_EQ(still.world_T_robot(3999).translation, Eigen::Vector3d::Zero());
}

}  // namespace
}  // namespace relslam::sim
