#include "relslam/sim/planar_simulator.hpp"
#include "relslam/sim/planar_sight.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace relslam::sim {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
// Robot-frame ends computed two ways (inverse_apply vs. the pose inverse): a few ulps of ~10.
constexpr double kFrameTolerance = 1e-12;

// Map A: four walls of length 8 at distance 5, facing in; a square of side 4.
PlanarMap four_planes(int loops = 2) {
  PlanarMap map;
  map.name = "A FourPlanes";
  map.world.walls = {Wall::between(0, {-4, -5}, {4, -5}), Wall::between(1, {5, -4}, {5, 4}),
                     Wall::between(2, {4, 5}, {-4, 5}), Wall::between(3, {-5, 4}, {-5, -4})};
  map.path.start = PlanarPose::from(-2, -2, 0);
  map.path.loops = loops;
  for (int side = 0; side < 4; ++side) {
    map.path.steps.push_back(PathOperation::move(4));
    map.path.steps.push_back(PathOperation::turn(90 * kDegree));
  }
  map.sensor.mode = PlaneVisibility::AlwaysVisible;
  return map;
}

bool same_bits(const PlaneSimFrame& x, const PlaneSimFrame& y) {
  if (x.observation.planes.size() != y.observation.planes.size()) return false;
  for (std::size_t i = 0; i < x.observation.planes.size(); ++i) {
    const PlaneObject &p = x.observation.planes[i], &q = y.observation.planes[i];
    const PlaneTruth &s = x.truth.planes[i], &t = y.truth.planes[i];
    if (p.a != q.a || p.b != q.b || p.y_lo != q.y_lo || p.y_hi != q.y_hi || p.iteration != q.iteration) return false;
    if (s.wall_id != t.wall_id || s.a_is_wall_end != t.a_is_wall_end || s.b_is_wall_end != t.b_is_wall_end)
      return false;
  }
  return x.truth.world_T_robot.translation == y.truth.world_T_robot.translation &&
         x.truth.world_T_robot.heading == y.truth.world_T_robot.heading;
}

TEST(PlanarSimulator, FourPlanesAlwaysVisibleAreExactRobotFrameWalls) {
  PlanarMap map = four_planes();
  map.sensor.noise = PlaneNoiseOptions::none();
  const PlanarSimulator sim(map, 1);
  ASSERT_EQ(sim.iterations(), 1 + 2 * 4 * (80 + 60));
  for (int k = 0; k < sim.iterations(); ++k) {
    const PlaneSimFrame f = sim.frame(k);
    ASSERT_EQ(f.observation.planes.size(), 4u) << "k " << k;
    const PlanarPose robot_T_world = f.truth.world_T_robot.inverse();
    for (int i = 0; i < 4; ++i) {
      const PlaneObject& p = f.observation.planes[i];
      const Wall& w = map.world.walls[i];
      ASSERT_EQ(f.truth.planes[i].wall_id, i) << "map order";
      ASSERT_NEAR((p.a - robot_T_world * w.a).norm(), 0, kFrameTolerance) << "k " << k << " wall " << i;
      ASSERT_NEAR((p.b - robot_T_world * w.b).norm(), 0, kFrameTolerance) << "k " << k << " wall " << i;
      ASSERT_GT(p.offset(), 0) << "every wall faces into the room";
    }
  }
  // At the start the robot at (−2, −2) faces +x: the south wall is 3 to its right (z = −3).
  const PlaneObject south = sim.frame(0).observation.planes[0];
  EXPECT_EQ(south.a, Eigen::Vector2d(-2, -3));
  EXPECT_EQ(south.b, Eigen::Vector2d(6, -3));
  EXPECT_EQ(sim.frame(0).truth.world_T_robot.translation, Eigen::Vector2d(-2, -2));
}

TEST(PlanarSimulator, RelativePoseOfTwoWallsDoesNotDependOnTheRobotPose) {
  // thesis 4.3.1: P1⁻¹ ∘ P2 is the same from every viewpoint (noise-free).
  PlanarMap map = four_planes(1);
  map.sensor.noise = PlaneNoiseOptions::none();
  const PlanarSimulator sim(map, 1);
  const PlaneSimFrame first = sim.frame(0);
  const PlanarPose expected = first.observation.planes[0].pose().inverse() * first.observation.planes[1].pose();
  for (int k = 1; k < sim.iterations(); k += 13) {
    const PlaneSimFrame f = sim.frame(k);
    const PlanarPose relative = f.observation.planes[0].pose().inverse() * f.observation.planes[1].pose();
    EXPECT_NEAR((relative.translation - expected.translation).norm(), 0, kFrameTolerance) << "k " << k;
    EXPECT_NEAR(wrap_angle(relative.heading - expected.heading), 0, kFrameTolerance) << "k " << k;
  }
}

TEST(PlanarSimulator, SameSeedGivesBitIdenticalFrames) {
  const PlanarSimulator a(four_planes(), 7), b(four_planes(), 7);
  for (int k = 0; k < a.iterations(); k += 3) ASSERT_TRUE(same_bits(a.frame(k), b.frame(k))) << "k " << k;
}

TEST(PlanarSimulator, FramesCanBeProducedInAnyOrder) {
  const PlanarSimulator sim(four_planes(), 7);
  const PlaneSimFrame late = sim.frame(500);
  for (int k = 0; k < 500; k += 7) sim.frame(k);
  EXPECT_TRUE(same_bits(late, sim.frame(500)));
}

TEST(PlanarSimulator, DifferentSeedGivesDifferentNoise) {
  const PlanarSimulator a(four_planes(), 7), b(four_planes(), 8);
  EXPECT_FALSE(same_bits(a.frame(10), b.frame(10)));
}

TEST(PlanarSimulator, FirstIterationSeeingCountsNoiseFreeReports) {
  PlanarMap map = four_planes(1);
  EXPECT_EQ(first_iteration_seeing(map, 4), 0);
  EXPECT_FALSE(first_iteration_seeing(map, 5));
  map.sensor.mode = PlaneVisibility::Scripted;
  map.world.walls[0].scripted_windows = {{5, 10}};
  map.world.walls[3].scripted_windows = {{8, 20}};
  EXPECT_EQ(first_iteration_seeing(map, 1), 5);
  EXPECT_EQ(first_iteration_seeing(map, 2), 8);
  EXPECT_FALSE(first_iteration_seeing(map, 3));
}

TEST(PlanarSimulator, BadWorldIsAnOptionError) {
  PlanarMap map = four_planes(1);
  map.world.walls[2].b = map.world.walls[2].a;
  try {
    PlanarSimulator sim(map, 1);
    FAIL();
  } catch (const OptionError& e) {
    EXPECT_EQ(e.field(), "walls[2].b");
  }
}

}  // namespace
}  // namespace relslam::sim
