// Scores of the planar half on hand-made cases with known answers.
#include "relslam/eval/metrics/plane_map_error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace relslam::eval {
namespace {

constexpr double kPi = std::numbers::pi;

PlaneObject wall(Eigen::Vector2d a, Eigen::Vector2d b) {
  PlaneObject p;
  p.a = a;
  p.b = b;
  return p;
}

TEST(PlaneError, AnExactPlaneScoresZeroEverywhere) {
  const PlaneObject w = wall({0, 5}, {8, 5});
  const PlaneError e = plane_error(w, w);
  EXPECT_EQ(e.ends, 0.0);
  EXPECT_EQ(e.angle_rad, 0.0);
  EXPECT_EQ(e.perpendicular, 0.0);
  EXPECT_EQ(e.length_ratio, 1.0);
}

TEST(PlaneError, AHalfSizePlaneOnItsWallPaysOnlyAtTheCutEnd) {
  const PlaneObject w = wall({0, 5}, {8, 5});
  const PlaneError e = plane_error(wall({0, 5}, {4, 5}), w);
  EXPECT_DOUBLE_EQ(e.ends, 2.0);  // ½(0 + 4)
  EXPECT_DOUBLE_EQ(e.perpendicular, 0.0);
  EXPECT_DOUBLE_EQ(e.length_ratio, 0.5);
}

// Without back-face culling a wall seen from behind is a plane with the opposite normal: its key
// point 1 is the wall's b end (Rule 14), and exactly placed it scores zero.
TEST(PlaneError, TheBackFaceIsScoredAgainstTheWallSeenFromBehind) {
  const PlaneObject w = wall({0, 5}, {8, 5});
  const PlaneError exact = plane_error(wall({8, 5}, {0, 5}), w);
  EXPECT_EQ(exact.ends, 0.0);
  EXPECT_EQ(exact.angle_rad, 0.0);
  EXPECT_EQ(exact.perpendicular, 0.0);
  const PlaneError shifted = plane_error(wall({8, 5.5}, {0, 5.5}), w);
  EXPECT_DOUBLE_EQ(shifted.ends, 0.5);
  EXPECT_DOUBLE_EQ(shifted.perpendicular, 0.5);
}

TEST(PlaneError, AShiftedAndTurnedPlaneGivesItsOffsetAndAngle) {
  const PlaneObject w = wall({-4, 0}, {4, 0});
  const PlaneObject shifted = w.transformed(PlanarPose::from(0, 0.3, 0));  // 0.3 off the line
  EXPECT_NEAR(plane_error(shifted, w).perpendicular, 0.3, 1e-15);
  EXPECT_NEAR(plane_error(shifted, w).ends, 0.3, 1e-15);
  const PlaneObject turned = w.transformed(PlanarPose::from(0, 0, 0.1));  // about its midpoint
  EXPECT_NEAR(plane_error(turned, w).angle_rad, 0.1, 1e-15);
  EXPECT_NEAR(plane_error(turned, w).perpendicular, 0.0, 1e-15);
  // Turned by more than 90° it faces the other way: the back face, turned by π − 0.1.
  const PlaneObject flipped = w.transformed(PlanarPose::from(0, 0, kPi / 2 + 0.2));
  EXPECT_NEAR(plane_error(flipped, w).angle_rad, kPi / 2 - 0.2, 1e-15);
}

TEST(PlanarPoseError, HeadingErrorWrapsAroundPi) {
  const PlanarPoseError e = planar_pose_error(PlanarPose::from(1, 1, kPi - 0.01), PlanarPose::from(1, 2, -kPi + 0.01));
  EXPECT_NEAR(e.heading_rad, 0.02, 1e-12);
  EXPECT_DOUBLE_EQ(e.position, 1.0);
  EXPECT_DOUBLE_EQ(e.axes.y(), -1.0);
}

TEST(WallVotes, MajorityWinsAndTiesGoToTheLowerWall) {
  WallVotes votes;
  votes.add(0, 3);
  votes.add(0, 3);
  votes.add(0, 1);
  votes.add(2, 5);
  votes.add(2, 4);
  votes.add(1, -1);  // unknown truth is no vote
  EXPECT_EQ(votes.wall_of(0), 3);
  EXPECT_EQ(votes.wall_of(2), 4);
  EXPECT_EQ(votes.wall_of(1), -1);
  EXPECT_EQ(votes.wall_of(9), -1);
}

TEST(PlaneMapError, SumsAndAveragesTheEndErrorOfPlanesWithAWall) {
  const std::vector<PlaneObject> walls = {wall({0, 0}, {4, 0}), wall({4, 0}, {4, 4})};
  WallVotes votes;
  votes.add(10, 0);
  votes.add(11, 1);
  const std::vector<std::pair<int, PlaneObject>> map = {
      {10, wall({0, 0}, {2, 0})},   // half size: e_ends 1
      {11, walls[1]},               // exact
      {12, wall({9, 9}, {10, 9})},  // no vote: not scored
  };
  const PlaneMapError e = plane_map_error(map, votes, walls);
  EXPECT_EQ(e.scored, 2);
  EXPECT_DOUBLE_EQ(e.sum, 1.0);
  EXPECT_DOUBLE_EQ(e.mean, 0.5);
}

}  // namespace
}  // namespace relslam::eval
