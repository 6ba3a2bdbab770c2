#include "relslam/sim/plane_sensor.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace relslam::sim {
namespace {

// Clipped ends are a + t·(b − a): a few ulps of coordinates of size ~10.
constexpr double kEndTolerance = 1e-12;
const double kTan30 = std::tan(30.0 * std::numbers::pi / 180.0);

PlanarWorld world_of(std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> segments) {
  PlanarWorld world;
  for (std::size_t i = 0; i < segments.size(); ++i)
    world.walls.push_back(Wall::between(static_cast<int>(i) + 10, segments[i].first, segments[i].second));
  return world;
}

PlaneSensorOptions exact(PlaneVisibility mode = PlaneVisibility::Frustum) {
  PlaneSensorOptions o;
  o.mode = mode;
  o.noise = PlaneNoiseOptions::none();
  return o;
}

// The robot at the world origin facing +x: robot and world frames coincide.
PlaneSimFrame look(const PlaneSensorOptions& o, const PlanarWorld& world, int k = 0, std::uint64_t seed = 1) {
  return PlaneSensor(o, seed).observe(world, PlanarPose::identity(), k);
}

void expect_point(const Eigen::Vector2d& actual, const Eigen::Vector2d& expected) {
  EXPECT_NEAR((actual - expected).norm(), 0.0, kEndTolerance) << actual.transpose() << " vs " << expected.transpose();
}

TEST(PlaneSensor, DefaultsAreValid) {
  const PlaneSensorOptions o;
  EXPECT_TRUE(check(o).empty());
  EXPECT_EQ(o.mode, PlaneVisibility::Frustum);
  EXPECT_TRUE(o.backface_cull);
  EXPECT_EQ(o.min_length, 0.05);
  EXPECT_FALSE(o.shuffle);
}

TEST(PlaneSensor, VisibilityNamesRoundTrip) {
  for (PlaneVisibility m :
       {PlaneVisibility::Frustum, PlaneVisibility::FullSize, PlaneVisibility::AlwaysVisible, PlaneVisibility::Scripted})
    EXPECT_EQ(parse_plane_visibility(to_string(m)), m);
  EXPECT_FALSE(parse_plane_visibility("always"));
}

TEST(PlaneSensor, CheckPrefixesFrustumAndNoiseFields) {
  PlaneSensorOptions o;
  o.frustum.far = 0;
  o.noise.position = -1;
  o.min_length = -0.1;
  const std::vector<OptionIssue> issues = check(o);
  ASSERT_EQ(issues.size(), 3u);
  EXPECT_EQ(issues[0].field, "frustum.far");
  EXPECT_EQ(issues[1].field, "noise.position");
  EXPECT_EQ(issues[2].field, "min_length");
  EXPECT_THROW(PlaneSensor(o, 1), OptionError);
}

TEST(PlaneSensor, FrustumModeReportsTheClippedPartAndMarksCutEnds) {
  // Both walls face the robot (front normal −x); the second has a real end inside the view.
  const PlanarWorld world = world_of({{{5, -10}, {5, 10}}, {{6, -1}, {6, 10}}});
  const PlaneSimFrame f = look(exact(), world, 7);
  ASSERT_EQ(f.observation.planes.size(), 2u);
  EXPECT_EQ(f.observation.iteration, 7);
  const PlaneObject& across = f.observation.planes[0];
  expect_point(across.a, {5, -5 * kTan30});
  expect_point(across.b, {5, 5 * kTan30});
  EXPECT_EQ(across.y_lo, 0.0);
  EXPECT_EQ(across.y_hi, 2.5);
  EXPECT_EQ(across.iteration, 7);
  EXPECT_EQ(f.truth.planes[0].wall_id, 10);
  EXPECT_FALSE(f.truth.planes[0].a_is_wall_end);
  EXPECT_FALSE(f.truth.planes[0].b_is_wall_end);

  const PlaneObject& ending = f.observation.planes[1];
  EXPECT_EQ(ending.a, Eigen::Vector2d(6, -1)) << "a real end is reported as it is";
  expect_point(ending.b, {6, 6 * kTan30});
  EXPECT_EQ(f.truth.planes[1].wall_id, 11);
  EXPECT_TRUE(f.truth.planes[1].a_is_wall_end);
  EXPECT_FALSE(f.truth.planes[1].b_is_wall_end);
  EXPECT_EQ(f.truth.world_T_robot.translation, Eigen::Vector2d::Zero());
}

TEST(PlaneSensor, OutputFollowsMapOrder) {
  // Nearer walls listed last still come last (Fig. 94).
  const PlanarWorld world = world_of({{{6, -1}, {6, 1}}, {{4, -1}, {4, 1}}, {{2, -1}, {2, 1}}});
  const PlaneSimFrame f = look(exact(), world);
  ASSERT_EQ(f.truth.planes.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(f.truth.planes[i].wall_id, 10 + i);
}

TEST(PlaneSensor, BackFaceCullingDropsWallsSeenFromBehind) {
  // Front normal +x: the robot at the origin is behind it.
  const PlanarWorld world = world_of({{{5, 10}, {5, -1}}});
  EXPECT_TRUE(look(exact(), world).observation.planes.empty());

  // Without culling it is seen with the face that looks at the robot: ends swapped, so the
  // left end (key point 1) is the real wall end at z = −1.
  PlaneSensorOptions o = exact();
  o.backface_cull = false;
  const PlaneSimFrame f = look(o, world);
  ASSERT_EQ(f.observation.planes.size(), 1u);
  const PlaneObject& p = f.observation.planes[0];
  EXPECT_EQ(p.a, Eigen::Vector2d(5, -1));
  expect_point(p.b, {5, 5 * kTan30});
  EXPECT_EQ(p.normal(), Eigen::Vector2d(-1, 0));
  EXPECT_GT(p.offset(), 0.0);
  EXPECT_TRUE(f.truth.planes[0].a_is_wall_end);
  EXPECT_FALSE(f.truth.planes[0].b_is_wall_end);
}

TEST(PlaneSensor, TwoSidedWallIsSeenFromBehindEvenWithCulling) {
  PlanarWorld world = world_of({{{5, 1}, {5, -1}}});
  world.walls[0].one_sided = false;
  const PlaneSimFrame f = look(exact(), world);
  ASSERT_EQ(f.observation.planes.size(), 1u);
  EXPECT_EQ(f.observation.planes[0].a, Eigen::Vector2d(5, -1));
  EXPECT_EQ(f.observation.planes[0].b, Eigen::Vector2d(5, 1));
}

TEST(PlaneSensor, PartsShorterThanTheMinimumLengthAreNotSeen) {
  const double edge = 5 * kTan30;  // the side edge at x = 5
  const PlanarWorld short_part = world_of({{{5, edge - 0.04}, {5, 10}}});
  const PlanarWorld long_part = world_of({{{5, edge - 0.06}, {5, 10}}});
  EXPECT_TRUE(look(exact(), short_part).observation.planes.empty());
  ASSERT_EQ(look(exact(), long_part).observation.planes.size(), 1u);
  EXPECT_NEAR(look(exact(), long_part).observation.planes[0].length(), 0.06, kEndTolerance);
  PlaneSensorOptions any_part = exact();
  any_part.min_length = 0;
  EXPECT_EQ(look(any_part, short_part).observation.planes.size(), 1u);
}

TEST(PlaneSensor, FullSizeReportsTheWholeWallOnceAnyPartIsSeen) {
  const PlanarWorld world = world_of({{{5, -1}, {5, 10}}, {{-5, 10}, {-5, -10}}});
  const PlaneSimFrame f = look(exact(PlaneVisibility::FullSize), world);
  ASSERT_EQ(f.observation.planes.size(), 1u) << "the wall behind the robot is outside the frustum";
  EXPECT_EQ(f.observation.planes[0].a, Eigen::Vector2d(5, -1));
  EXPECT_EQ(f.observation.planes[0].b, Eigen::Vector2d(5, 10));
  EXPECT_TRUE(f.truth.planes[0].a_is_wall_end && f.truth.planes[0].b_is_wall_end);
}

TEST(PlaneSensor, AlwaysVisibleIgnoresTheFrustum) {
  // Behind the robot and facing it (front normal +x).
  const PlanarWorld world = world_of({{{-5, 10}, {-5, -10}}});
  const PlaneSimFrame f = look(exact(PlaneVisibility::AlwaysVisible), world);
  ASSERT_EQ(f.observation.planes.size(), 1u);
  EXPECT_EQ(f.observation.planes[0].a, Eigen::Vector2d(-5, 10));
  EXPECT_EQ(f.observation.planes[0].b, Eigen::Vector2d(-5, -10));
}

TEST(PlaneSensor, ScriptedWindowsDecideVisibility) {
  PlanarWorld world = world_of({{{-5, 10}, {-5, -10}}, {{5, -1}, {5, 1}}});
  world.walls[0].scripted_windows = {{2, 4}, {8, 8}};
  const PlaneSensorOptions o = exact(PlaneVisibility::Scripted);
  std::vector<int> seen;
  for (int k = 0; k < 12; ++k) {
    const PlaneSimFrame f = look(o, world, k);
    if (f.observation.planes.empty()) continue;
    ASSERT_EQ(f.observation.planes.size(), 1u) << "the unscripted wall is never seen, frustum or not";
    EXPECT_EQ(f.truth.planes[0].wall_id, 10);
    EXPECT_EQ(f.observation.planes[0].length(), 20.0) << "full size";
    seen.push_back(k);
  }
  EXPECT_EQ(seen, (std::vector<int>{2, 3, 4, 8}));
}

TEST(PlaneSensor, WallSeenEdgeOnIsCulledOrFlipsWithTheNoise) {
  // The robot stands on the wall's line and looks along it, as Map C's robot turning at (36, 0)
  // on the line x = 36 (thesis Fig. 72).
  const PlanarWorld world = world_of({{{2, 0}, {6, 0}}});
  EXPECT_TRUE(look(exact(), world).observation.planes.empty()) << "culled: the robot is not in front";

  PlaneSensorOptions o = exact();
  o.backface_cull = false;
  const PlaneSimFrame f = look(o, world);
  ASSERT_EQ(f.observation.planes.size(), 1u) << "without noise neither face looks at the robot; reported as stored";
  EXPECT_EQ(f.observation.planes[0].a, Eigen::Vector2d(2, 0));
  EXPECT_EQ(f.observation.planes[0].b, Eigen::Vector2d(6, 0));

  o.noise = PlaneNoiseOptions::with_noise();
  int facing_left = 0, facing_right = 0;
  for (int k = 0; k < 200; ++k) {
    const PlaneSimFrame noisy = look(o, world, k);
    ASSERT_EQ(noisy.observation.planes.size(), 1u) << "k " << k;
    const PlaneObject& p = noisy.observation.planes[0];
    EXPECT_GE(p.offset(), -kEndTolerance) << "k " << k << ": the reported face must look at the robot";
    (p.normal().y() > 0 ? facing_left : facing_right) += 1;
  }
  EXPECT_GT(facing_left, 40);
  EXPECT_GT(facing_right, 40);
}

TEST(PlaneSensor, NoiseMovesTheWholeWallBeforeClipping) {
  PlaneSensorOptions o = exact();
  o.noise.model = PlaneNoiseModel::Gaussian;
  o.noise.position = 0.1;
  o.noise.rotation_rad = 2.0 * std::numbers::pi / 180.0;
  const PlanarWorld world = world_of({{{5, -1}, {5, 10}}});
  double shortest = 1e9, longest = 0;
  for (int k = 0; k < 50; ++k) {
    const PlaneSimFrame f = look(o, world, k, 3);
    ASSERT_EQ(f.observation.planes.size(), 1u);
    const PlaneObject& p = f.observation.planes[0];
    // The real end moved with the wall's noise ...
    const auto noisy = draw_wall_noise(o.noise, 3, 10, k).apply(world.walls[0].a, world.walls[0].b);
    EXPECT_EQ(p.a, noisy.first) << "k " << k;
    // ... while the cut end stays on the frustum's edge, so the visible length changes.
    EXPECT_NEAR(p.b.y(), p.b.x() * kTan30, kEndTolerance) << "k " << k;
    shortest = std::min(shortest, p.length());
    longest = std::max(longest, p.length());
  }
  EXPECT_GT(longest - shortest, 0.1);
}

TEST(PlaneSensor, ShuffleReordersPlanesAndTheirTruthTogether) {
  PlanarWorld world;
  for (int i = 0; i < 6; ++i) world.walls.push_back(Wall::between(i, {4 + i, -1.0}, {4 + i, 1.0}));
  PlaneSensorOptions o = exact(PlaneVisibility::AlwaysVisible);
  o.shuffle = true;
  int reordered = 0;
  for (int k = 0; k < 20; ++k) {
    const PlaneSimFrame f = look(o, world, k);
    ASSERT_EQ(f.observation.planes.size(), 6u);
    std::vector<int> ids;
    for (std::size_t i = 0; i < 6; ++i) {
      const int id = f.truth.planes[i].wall_id;
      EXPECT_EQ(f.observation.planes[i].a, world.walls[id].a) << "truth must follow its plane";
      ids.push_back(id);
    }
    reordered += !std::is_sorted(ids.begin(), ids.end());
    std::sort(ids.begin(), ids.end());
    EXPECT_EQ(ids, (std::vector<int>{0, 1, 2, 3, 4, 5}));
  }
  EXPECT_GT(reordered, 15);
}

}  // namespace
}  // namespace relslam::sim
