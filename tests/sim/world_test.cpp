#include "relslam/sim/world.hpp"

#include <gtest/gtest.h>

namespace relslam::sim {
namespace {

TEST(World, LandmarkCountFollowsDensityPerHundredUnits) {
  SimOptions o;
  for (double density : {25.0, 100.0, 550.0}) {
    o.density = density;
    const Path path(o);
    EXPECT_EQ(World(o, path, 1).size(), std::lround(density * 1145.0 / 100.0)) << "density " << density;
  }
}

TEST(World, SizeIsTheLandmarkCountTheOptionsGive) {
  SimOptions o;
  o.path = PathKind::Line;
  o.iterations = 700;
  o.density = 30;
  const Path path(o);
  EXPECT_EQ(World(o, path, 1).size(), landmark_count(o));
}

TEST(World, DenserFieldExtendsTheSparserOneWithTheSameSeed) {
  SimOptions sparse, dense;
  sparse.density = 50;
  dense.density = 100;
  const World a(sparse, Path(sparse), 9), b(dense, Path(dense), 9);
  for (int id = 0; id < a.size(); ++id) ASSERT_EQ(a.anchors()[id], b.anchors()[id]) << "id " << id;
}

TEST(World, PointsLieInTheBandAroundTheStartSegment) {
  // The first straight runs 129.6 units from the start along +z (the start heading). In the
  // window z in [35, 50], |x| < 30 no other part of the band reaches (the crossing line is at
  // 60°, the right circle's band starts beyond z = 51.8), so every point there belongs to the
  // first straight: within band_half_width of the line and band_half_height of the incline.
  SimOptions o;
  o.density = 550;
  const Path path(o);
  const World world(o, path, 2);
  int checked = 0;
  for (const Eigen::Vector3d& p : world.anchors()) {
    if (p.z() < 35 || p.z() > 50 || std::abs(p.x()) > 30) continue;
    const double incline = 20.0 * (1.0 - std::cos(2.0 * M_PI * p.z() / 1145.0)) / 2.0;
    EXPECT_LE(std::abs(p.x()), 15.0 + 1e-9) << p.transpose();
    EXPECT_LE(std::abs(p.y() - incline), 5.0 + 1e-9) << p.transpose();
    ++checked;
  }
  EXPECT_GT(checked, 40);
}

TEST(World, DynamicCountPicksPointsVisibleAtTheStart) {
  SimOptions o;
  o.density = 25;
  o.dynamic.count = 2;
  const Path path(o);
  const World world(o, path, 3);
  ASSERT_EQ(world.dynamic_count(), 2);
  for (int id : world.dynamic_ids()) {
    EXPECT_TRUE(o.frustum.contains(world.anchors()[id])) << "id " << id;
    EXPECT_TRUE(o.frustum.contains(path.world_T_robot(100).inverse_apply(world.anchors()[id]))) << "still seen at 100";
    // It moves: positions differ across iterations, but stay within the amplitude per axis.
    double moved = 0;
    for (int k = 0; k < 400; k += 10) {
      const Eigen::Vector3d offset = world.position(id, k) - world.anchors()[id];
      moved = std::max(moved, offset.norm());
      EXPECT_LE(std::abs(offset.x()), 4.0 + 1e-12);
      EXPECT_LE(std::abs(offset.y()), 1.2 + 1e-12);
      EXPECT_LE(std::abs(offset.z()), 4.0 + 1e-12);
    }
    EXPECT_GT(moved, 1.0);
  }
}

TEST(World, DynamicFractionTurnsThatShareOfAllPoints) {
  SimOptions o;
  o.dynamic.fraction = 0.03;
  const Path path(o);
  const World world(o, path, 4);
  EXPECT_EQ(world.dynamic_count(), std::lround(0.03 * world.size()));
}

TEST(World, TooManyDynamicPointsIsAnOptionErrorOnDynamicCount) {
  SimOptions o;
  o.density = 25;
  o.dynamic.count = 1000;
  const Path path(o);
  try {
    World(o, path, 5);
    FAIL() << "expected OptionError";
  } catch (const OptionError& e) {
    EXPECT_EQ(e.field(), "dynamic.count");
    EXPECT_NE(e.problem().find("visible at iteration 0 and 100"), std::string::npos) << e.problem();
  }
}

}  // namespace
}  // namespace relslam::sim
