#include "relslam/sim/map_generator.hpp"

#include "relslam/sim/planar_sight.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace relslam::sim {
namespace {

// The least distance from p to the wall, from the wall's own frame (independent of the
// generator's geometry helpers).
double distance_to_wall(const Eigen::Vector2d& p, const Wall& w) {
  const double along = std::clamp((p - w.a).dot(w.tangent()), 0.0, w.length());
  return (w.a + along * w.tangent() - p).norm();
}

void expect_same(const PlanarMap& x, const PlanarMap& y) {
  ASSERT_EQ(x.world.walls.size(), y.world.walls.size());
  for (std::size_t i = 0; i < x.world.walls.size(); ++i) {
    EXPECT_EQ(x.world.walls[i].a, y.world.walls[i].a);
    EXPECT_EQ(x.world.walls[i].b, y.world.walls[i].b);
    EXPECT_EQ(x.world.walls[i].one_sided, y.world.walls[i].one_sided);
  }
  const PlanarPath px(x.path), py(y.path);
  ASSERT_EQ(px.iterations(), py.iterations());
  for (int k = 0; k < px.iterations(); ++k) {
    EXPECT_EQ(px.world_T_robot(k).translation, py.world_T_robot(k).translation);
    EXPECT_EQ(px.world_T_robot(k).heading, py.world_T_robot(k).heading);
  }
}

TEST(MapGenerator, SameOptionsGiveTheSameMapBitForBit) {
  for (MapFamily family : generated_families()) {
    SCOPED_TRACE(std::string(to_string(family)));
    const MapGeneratorOptions options{family, 7, 0.75};
    expect_same(generate_map(options), generate_map(options));
    const PlanarMap other = generate_map({family, 8, 0.75});
    EXPECT_NE(generate_map(options).world.walls.front().a, other.world.walls.front().a) << "seeds 7 and 8 alike";
  }
}

TEST(MapGenerator, RefusesNoFamilyAndAClearanceTheCorridorsCannotKeep) {
  EXPECT_THROW(generate_map({MapFamily::None, 1, 0.75}), OptionError);
  const std::vector<OptionIssue> issues = check(MapGeneratorOptions{MapFamily::Corridor, 1, 2.0});
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues.front().field, "clearance");
}

// Over many seeds each family's map has walls of real length, a path that crosses no wall and
// keeps the clearance from every wall at every pose, and sees two walls at once in both frusta.
TEST(MapGenerator, EveryFamilyIsValidOverManySeeds) {
  constexpr int kSeeds = 25;
  for (MapFamily family : generated_families()) {
    for (int seed = 1; seed <= kSeeds; ++seed) {
      SCOPED_TRACE(std::string(to_string(family)) + " seed " + std::to_string(seed));
      const double clearance = seed % 2 ? 0.75 : 1.0;
      const PlanarMap map = generate_map({family, static_cast<std::uint64_t>(seed), clearance});
      ASSERT_GE(map.world.walls.size(), 4u);
      for (const Wall& w : map.world.walls) {
        EXPECT_GE(w.length(), kMinGeneratedWall);
        EXPECT_TRUE(w.a.allFinite() && w.b.allFinite());
      }
      const PlanarPath path(map.path);
      EXPECT_GT(path.iterations(), 200);
      EXPECT_FALSE(first_wall_crossing(map, path).has_value());
      EXPECT_FALSE(first_exit_from_map(map, path).has_value());
      double least = std::numeric_limits<double>::infinity();
      for (int k = 0; k < path.iterations(); ++k)
        for (const Wall& w : map.world.walls) least = std::min(least, distance_to_wall(path.world_T_robot(k).translation, w));
      EXPECT_GE(least, clearance - 1e-9);
      for (const char* preset : {"small", "large"}) {
        PlanarMap seen = map;
        seen.sensor.frustum = *frustum_preset(preset);
        EXPECT_TRUE(first_iteration_seeing(seen, path, 2).has_value()) << preset;
      }
    }
  }
}

// The families' shapes: rooms of 4-8 walls; corridors turn 180 degrees at their dead ends.
TEST(MapGenerator, ConvexRoomsHaveFourToEightWallsAndCorridorsTurnAroundAtDeadEnds) {
  for (int seed = 1; seed <= 20; ++seed) {
    const PlanarMap room = generate_map({MapFamily::ConvexRoom, static_cast<std::uint64_t>(seed), 0.75});
    EXPECT_GE(room.world.walls.size(), 4u);
    EXPECT_LE(room.world.walls.size(), 8u);
    for (MapFamily family : {MapFamily::Corridor, MapFamily::MirroredCorridor}) {
      const PlanarMap c = generate_map({family, static_cast<std::uint64_t>(seed), 0.75});
      const auto& steps = c.path.steps;
      EXPECT_GE(std::count_if(steps.begin(), steps.end(),
                              [](const PathOperation& op) {
                                return op.kind == PathOperationKind::Turn && op.angle_rad == std::numbers::pi;
                              }),
                2)
          << "seed " << seed;
    }
  }
}

// Mirrored pieces: every wall piece along the corridor has a partner of the same length
// across it.
TEST(MapGenerator, MirroredCorridorPiecesComeInPairsOfEqualLength) {
  for (int seed = 1; seed <= 10; ++seed) {
    const PlanarMap c = generate_map({MapFamily::MirroredCorridor, static_cast<std::uint64_t>(seed), 0.75});
    int paired = 0;
    for (const Wall& w : c.world.walls)
      for (const Wall& v : c.world.walls)
        if (&w != &v && std::abs(w.length() - v.length()) < 1e-9 && w.normal().dot(v.normal()) < -0.999) {
          ++paired;
          break;
        }
    EXPECT_GE(paired, static_cast<int>(c.world.walls.size()) / 2) << "seed " << seed;
  }
}

}  // namespace
}  // namespace relslam::sim
