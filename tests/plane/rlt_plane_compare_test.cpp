#include "relslam/plane/rlt_plane_compare.hpp"

#include "plane_world_fixture.hpp"
#include "relslam/plane/rlt_plane.hpp"
#include "seeded_random.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace relslam::plane {
namespace {

constexpr double kExact = 1e-12;  // spec §8: Rule 3 invariance to 1e-12
constexpr double kPi = std::numbers::pi;

// E01 (Fig 66): two walls seen from 50 random robot poses.
TEST(PlaneOffset, Rule3OffsetIsTheSameFromEveryRobotPose) {
  const PlaneObject wall1{{-4, -5}, {4, -5}}, wall2{{5, -4}, {5, 4}};
  const PlanarPose expected = wall1.pose().inverse() * wall2.pose();
  relslam::test::SeededRandom random(11);
  double raw_spread = 0;
  PlanarPose first_raw;
  for (int i = 0; i < 50; ++i) {
    const PlanarPose robot = PlanarPose::from(random.uniform(-3, 3), random.uniform(-3, 3), random.uniform(-kPi, kPi));
    const PlaneObject seen1 = wall1.transformed(robot.inverse()), seen2 = wall2.transformed(robot.inverse());
    const PlanarPose offset = plane_offset(seen1, seen2);
    EXPECT_LT((offset.translation - expected.translation).norm(), kExact) << "pose " << i;
    EXPECT_NEAR(wrap_angle(offset.heading - expected.heading), 0, kExact) << "pose " << i;
    // Without Rule 3 the difference is translation-invariant only: it turns with the robot.
    const PlanarPose raw = plane_offset(seen1, seen2, false);
    if (i == 0) first_raw = raw;
    raw_spread = std::max(raw_spread, (raw.translation - first_raw.translation).norm());
  }
  EXPECT_GT(raw_spread, 1.0);
}

// Two RltPlanes from a run of the four planes world.
struct TwoPlanes {
  RltPlane first, second;
};

TwoPlanes record(const std::vector<int>& first_iterations, const std::vector<int>& second_iterations) {
  const std::vector<test::Wall> walls = test::four_planes_walls();
  const std::vector<PlanarPose> path = test::four_planes_path(1, 0.25, 10 * kPi / 180);
  const auto seen = [&](int wall, int t) { return test::observe(walls, path[t], t, {.always = true}).planes[wall]; };
  TwoPlanes planes{RltPlane(0, seen(0, first_iterations[0]), 100), RltPlane(1, seen(1, second_iterations[0]), 100)};
  for (std::size_t k = 1; k < first_iterations.size(); ++k) planes.first.add(seen(0, first_iterations[k]));
  for (std::size_t k = 1; k < second_iterations.size(); ++k) planes.second.add(seen(1, second_iterations[k]));
  return planes;
}

TEST(ComparePlanes, AveragesOnlyTheIterationsBothPlanesWereSeenIn) {
  const TwoPlanes p = record({0, 1, 2, 3, 5, 8, 9, 12}, {1, 2, 4, 5, 6, 9, 10, 11});
  const CompareResult r = compare_planes(p.first, p.second);
  ASSERT_TRUE(r.valid);
  EXPECT_EQ(r.samples, 4);  // 1, 2, 5, 9
  EXPECT_EQ(r.interval.start, 1);
  EXPECT_EQ(r.interval.end, 9);
  const PlanarPose expected = PlaneObject{{-4, -5}, {4, -5}}.pose().inverse() * PlaneObject{{5, -4}, {5, 4}}.pose();
  EXPECT_LT((r.delta.translation - expected.translation).norm(), kExact);
  EXPECT_NEAR(wrap_angle(r.delta.heading - expected.heading), 0, kExact);
  EXPECT_NEAR(r.length1, 8, kExact);
  EXPECT_NEAR(r.height2, 2.5, kExact);
}

TEST(ComparePlanes, GroupModeKeepsToTheGivenInterval) {
  const TwoPlanes p = record({0, 1, 2, 3, 4, 5}, {0, 1, 2, 3, 4, 5});
  RltPlaneInterval within;
  for (int t : {2, 3, 5}) within.add(t);
  const CompareResult r = compare_planes(p.first, p.second, true, &within);
  EXPECT_EQ(r.samples, 3);
  EXPECT_EQ(r.interval.start, 2);
  EXPECT_EQ(r.interval.end, 5);
}

TEST(ComparePlanes, NoCommonIterationIsInvalid) {
  const TwoPlanes p = record({0, 1, 2}, {4, 5});
  EXPECT_FALSE(compare_planes(p.first, p.second).valid);
}

}  // namespace
}  // namespace relslam::plane
