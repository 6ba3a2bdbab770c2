// The motion between two scans from their walls: exact on noise-free walls from a guess that is
// off by a whole step, the guess kept along what the walls leave open (a corridor), and the guess returned
// unused with too few walls.
#include "relslam/scan/wall_registration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace relslam::scan {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Walls given in the world (= previous robot frame), ends in the order that faces the origin.
PlaneObject wall(double ax, double az, double bx, double bz) {
  PlaneObject p;
  p.a = {ax, az};
  p.b = {bx, bz};
  return p;
}

// A room's walls seen from the origin (front towards the robot) and a pillar's face.
std::vector<PlaneObject> room() {
  return {wall(6, -3, 6, 3), wall(6, 3, -2, 3), wall(-2, -3, 6, -3), wall(3, -0.5, 3, 1.5)};
}

// The same walls seen from the robot at previous_T_current.
std::vector<PlaneObject> seen_from(const std::vector<PlaneObject>& walls, const PlanarPose& previous_T_current) {
  std::vector<PlaneObject> out;
  for (const PlaneObject& w : walls) out.push_back(w.transformed(previous_T_current.inverse()));
  return out;
}

TEST(WallRegistration, RecoversAStepExactlyFromIdentity) {
  // Within the default bounds of the first pairing (0.5 m, 10°) for every wall.
  const PlanarPose motion = PlanarPose::from(0.35, 0.1, 6.0 * kDeg);
  const WallRegistration r = register_walls(room(), seen_from(room(), motion), PlanarPose::identity());
  ASSERT_TRUE(r.used);
  EXPECT_EQ(r.pairs, 4);
  EXPECT_NEAR(r.previous_T_current.translation.x(), 0.35, 1e-6);
  EXPECT_NEAR(r.previous_T_current.translation.y(), 0.1, 1e-6);
  EXPECT_NEAR(r.previous_T_current.heading, 6.0 * kDeg, 1e-8);
  EXPECT_LT(r.rms, 1e-6);
}

TEST(WallRegistration, KeepsTheGuessAlongACorridor) {
  // Two parallel walls: the motion across them and the turn are measured, the motion along
  // them is the guess's.
  const std::vector<PlaneObject> corridor = {wall(10, 1, -5, 1), wall(-5, -1, 10, -1)};
  const PlanarPose motion = PlanarPose::from(0.5, 0.2, 3.0 * kDeg);
  const PlanarPose guess = PlanarPose::from(0.3, 0.0, 0.0);
  const WallRegistration r = register_walls(corridor, seen_from(corridor, motion), guess);
  ASSERT_TRUE(r.used);
  EXPECT_NEAR(r.previous_T_current.heading, 3.0 * kDeg, 1e-6);
  // Across: the robot's z is measured exactly; along: the guess's x stands.
  EXPECT_NEAR(r.previous_T_current.translation.y(), 0.2, 0.02);
  EXPECT_NEAR(r.previous_T_current.translation.x(), 0.3, 0.05);
}

TEST(WallRegistration, ReturnsTheGuessWithTooFewWalls) {
  const std::vector<PlaneObject> one = {wall(6, -3, 6, 3)};
  const PlanarPose guess = PlanarPose::from(0.1, 0.0, 0.0);
  const WallRegistration r = register_walls(one, seen_from(one, PlanarPose::from(0.4, 0, 0)), guess);
  EXPECT_FALSE(r.used);
  EXPECT_EQ(r.previous_T_current.translation, guess.translation);
}

}  // namespace
}  // namespace relslam::scan
