#include "relslam/sim/planar_world.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace relslam::sim {
namespace {

TEST(PlanarWorld, FrontNormalIsTheTangentTurnedPlusNinetyDegrees) {
  // Map A's south wall z = −5 runs towards +x and faces +z, into the room.
  const Wall south = Wall::between(0, {-4, -5}, {4, -5});
  EXPECT_EQ(south.normal(), Eigen::Vector2d(0, 1));
  EXPECT_EQ(south.length(), 8.0);
  EXPECT_TRUE(south.faces({0, 0}));
  EXPECT_FALSE(south.faces({0, -6}));
  EXPECT_FALSE(south.faces({10, -5})) << "a point on the wall's line sees it edge-on: not its front";
}

TEST(PlanarWorld, CheckNamesTheWallAndTheProblem) {
  PlanarWorld world;
  world.walls = {Wall::between(0, {0, 0}, {1, 0}), Wall::between(1, {2, 2}, {2, 2}), Wall::between(0, {0, NAN}, {1, 1}),
                 Wall::between(3, {0, 0}, {0, 1})};
  world.walls[3].height = 0;
  world.walls[3].scripted_windows = {{5, 4}};
  const std::vector<OptionIssue> issues = check(world);
  ASSERT_EQ(issues.size(), 5u);
  EXPECT_EQ(issues[0].field, "walls[1].b");
  EXPECT_EQ(issues[0].problem, "equals a [2, 2]; a wall needs two distinct ends");
  EXPECT_EQ(issues[1].field, "walls[2].a");
  EXPECT_EQ(issues[1].problem, "must be a finite point, got [0, nan]");
  EXPECT_EQ(issues[2].field, "walls[2].id");
  EXPECT_EQ(issues[2].problem, "repeats the id 0 of walls[0]");
  EXPECT_EQ(issues[3].field, "walls[3].height");
  EXPECT_EQ(issues[4].field, "walls[3].scripted_windows[0]");
  EXPECT_EQ(issues[4].problem, "must be [first, last] with 0 <= first <= last, got [5, 4]");
}

TEST(PlanarWorld, IterationWindowsIncludeBothEnds) {
  const IterationWindow w{10, 20};
  EXPECT_FALSE(w.contains(9));
  EXPECT_TRUE(w.contains(10));
  EXPECT_TRUE(w.contains(20));
  EXPECT_FALSE(w.contains(21));
}

}  // namespace
}  // namespace relslam::sim
