#include "relslam/sim/planar_path.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace relslam::sim {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
// Step lengths are differences of poses of size ~10: a few ulps.
constexpr double kStepTolerance = 1e-12;

PathProgram program(PlanarPose start, std::vector<PathOperation> steps, int loops = 1) {
  PathProgram p;
  p.start = start;
  p.steps = std::move(steps);
  p.loops = loops;
  return p;
}

TEST(PlanarPath, MoveEndsExactlyOnTheTargetAfterFullSpeedSteps) {
  const PlanarPath path(program(PlanarPose::from(-2, -2, 0), {PathOperation::move(4)}));
  ASSERT_EQ(path.iterations(), 81) << "the start pose plus 80 steps of 0.05";
  EXPECT_EQ(path.world_T_robot(0).translation, Eigen::Vector2d(-2, -2));
  EXPECT_EQ(path.world_T_robot(80).translation, Eigen::Vector2d(2, -2));
  EXPECT_EQ(path.world_T_robot(80).heading, 0.0);
  for (int k = 1; k <= 80; ++k) {
    const Eigen::Vector2d step = path.world_T_robot(k).translation - path.world_T_robot(k - 1).translation;
    EXPECT_NEAR(step.x(), 0.05, kStepTolerance) << "k " << k;
    EXPECT_EQ(step.y(), 0.0) << "k " << k;
  }
}

TEST(PlanarPath, LastStepOfAnOperationIsShortened) {
  const PlanarPath path(program(PlanarPose::identity(), {PathOperation::move(1.03)}));
  ASSERT_EQ(path.iterations(), 22) << "20 full steps and one of 0.03";
  EXPECT_EQ(path.world_T_robot(21).translation.x(), 1.03);
  EXPECT_NEAR(path.world_T_robot(21).translation.x() - path.world_T_robot(20).translation.x(), 0.03, kStepTolerance);
}

TEST(PlanarPath, TurnIsInPlaceAndEndsOnTheTargetHeading) {
  const PlanarPose start = PlanarPose::from(28.5, 1.5, 0);
  const PlanarPath path(program(start, {PathOperation::turn(90 * kDegree)}));
  ASSERT_EQ(path.iterations(), 61);
  for (int k = 0; k < path.iterations(); ++k)
    ASSERT_EQ(path.world_T_robot(k).translation, start.translation) << "k " << k << " moved during a turn";
  EXPECT_EQ(path.world_T_robot(60).heading, wrap_angle(90 * kDegree));
  EXPECT_NEAR(path.world_T_robot(1).heading, 1.5 * kDegree, kStepTolerance);
}

TEST(PlanarPath, NegativeTurnGoesClockwiseWithAShortLastStep) {
  const PlanarPath path(program(PlanarPose::identity(), {PathOperation::turn(-100 * kDegree)}));
  ASSERT_EQ(path.iterations(), 68) << "66 steps of 1.5° and one of 1°";
  EXPECT_NEAR(path.world_T_robot(1).heading, -1.5 * kDegree, kStepTolerance);
  EXPECT_EQ(path.world_T_robot(67).heading, wrap_angle(-100 * kDegree));
}

TEST(PlanarPath, ArcEndsOnItsCircle) {
  // A quarter circle of radius 2 to the left: from the origin facing +x to (2, 2) facing +z.
  const double radius = 2;
  const PlanarPath path(
      program(PlanarPose::identity(), {PathOperation::arc(radius * std::numbers::pi / 2, 90 * kDegree)}));
  const PlanarPose end = path.world_T_robot(path.iterations() - 1);
  EXPECT_NEAR(end.translation.x(), 2, kStepTolerance);
  EXPECT_NEAR(end.translation.y(), 2, kStepTolerance);
  EXPECT_EQ(end.heading, wrap_angle(90 * kDegree));
  // 3.14 units at 0.05 take 63 steps, 90° at 1.5° only 60: the move sets the pace.
  EXPECT_EQ(path.iterations(), 64);
  for (int k = 0; k < path.iterations(); ++k)
    EXPECT_NEAR((path.world_T_robot(k).translation - Eigen::Vector2d(0, radius)).norm(), radius, kStepTolerance)
        << "k " << k;
}

TEST(PlanarPath, SquareLoopsReturnToTheStartEveryLoop) {
  // Map A's path: MOVE 4, TURN +90, four times, counter-clockwise, 10 loops.
  std::vector<PathOperation> square;
  for (int side = 0; side < 4; ++side) {
    square.push_back(PathOperation::move(4));
    square.push_back(PathOperation::turn(90 * kDegree));
  }
  const PlanarPose start = PlanarPose::from(-2, -2, 0);
  const PlanarPath path(program(start, square, 10));
  ASSERT_EQ(path.iterations(), 1 + 10 * 4 * (80 + 60));
  ASSERT_EQ(path.operation_ends().size(), 80u);
  const Eigen::Vector2d corners[] = {{2, -2}, {2, 2}, {-2, 2}, {-2, -2}};
  for (std::size_t op = 0; op < path.operation_ends().size(); op += 2) {
    const PlanarPose& at = path.world_T_robot(path.operation_ends()[op]);
    EXPECT_NEAR((at.translation - corners[(op / 2) % 4]).norm(), 0, kStepTolerance) << "move " << op / 2;
  }
  const PlanarPose& end = path.world_T_robot(path.iterations() - 1);
  EXPECT_NEAR((end.translation - start.translation).norm(), 0, kStepTolerance);
  EXPECT_NEAR(wrap_angle(end.heading - start.heading), 0, kStepTolerance);
}

TEST(PlanarPath, ThenRunsOnceAfterTheLoops) {
  PathProgram p = program(PlanarPose::identity(), {PathOperation::move(1), PathOperation::turn(std::numbers::pi)}, 2);
  p.then = {PathOperation::move(0.5)};
  const PlanarPath path(p);
  EXPECT_EQ(path.iterations(), iteration_count(p));
  EXPECT_EQ(path.iterations(), 1 + 2 * (20 + 120) + 10);
  ASSERT_EQ(path.operation_ends().size(), 5u);
  EXPECT_NEAR((path.world_T_robot(path.iterations() - 1).translation - Eigen::Vector2d(0.5, 0)).norm(), 0,
              kStepTolerance);
}

TEST(PlanarPath, DefaultsAreValid) {
  PathProgram p;
  p.steps = {PathOperation::move(1)};
  EXPECT_TRUE(check(p).empty());
  EXPECT_EQ(p.speed, 0.05);
  EXPECT_DOUBLE_EQ(p.turn_rate_rad, 1.5 * kDegree);
}

TEST(PlanarPath, CheckNamesEachBadOperation) {
  PathProgram p;
  p.speed = 0;
  p.steps = {PathOperation::move(-1), PathOperation::turn(0), PathOperation::arc(2, NAN)};
  const std::vector<OptionIssue> issues = check(p);
  ASSERT_EQ(issues.size(), 4u);
  EXPECT_EQ(issues[0].field, "speed");
  EXPECT_EQ(issues[0].problem, "must be > 0, got 0");
  EXPECT_EQ(issues[1].field, "steps[0].distance");
  EXPECT_EQ(issues[1].problem, "must be > 0, got -1");
  EXPECT_EQ(issues[2].field, "steps[1].angle_deg");
  EXPECT_EQ(issues[2].problem, "must be a finite non-zero angle, got 0");
  EXPECT_EQ(issues[3].field, "steps[2].angle_deg");
  EXPECT_THROW(PlanarPath{p}, OptionError);
}

TEST(PlanarPath, EmptyProgramAndHugePathsAreRejected) {
  PathProgram p;
  ASSERT_EQ(check(p).size(), 1u);
  EXPECT_EQ(check(p)[0].problem, "is empty; a path needs at least one MOVE, TURN or ARC");
  p.steps = {PathOperation::move(1e300)};
  ASSERT_EQ(check(p).size(), 1u);
  EXPECT_EQ(check(p)[0].field, "steps");
}

}  // namespace
}  // namespace relslam::sim
