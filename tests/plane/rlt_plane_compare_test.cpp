#include "relslam/plane/rlt_plane_compare.hpp"

#include "plane_world_fixture.hpp"
#include "relslam/plane/rlt_plane.hpp"
#include "seeded_random.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace relslam::plane {
namespace {

constexpr double kExact = 1e-12;  // Rule 3 invariance to 1e-12
constexpr double kPi = std::numbers::pi;

// Whether both walls' midpoints lie ahead of the robot within ±60° of its heading: E01's poses
// have both walls in view, here of a wide viewing cone.
bool both_in_view(const PlanarPose& robot, const PlaneObject& wall1, const PlaneObject& wall2) {
  const auto ahead = [&](const PlaneObject& wall) {
    const Eigen::Vector2d m = robot.inverse_apply(wall.midpoint());
    return m.x() > 0 && std::abs(std::atan2(m.y(), m.x())) < kPi / 3;
  };
  return ahead(wall1) && ahead(wall2);
}

// E01 (Fig 66; Rule 3, thesis 4.3.1): two walls seen from 50 random robot poses with both in
// view. The Rule 3 offset is the same from each to 1e-12; the raw midpoint difference is the
// world difference turned by the robot's heading, so it changes with the heading.
TEST(PlaneOffset, Rule3OffsetIsTheSameFromEveryRobotPose) {
  const PlaneObject wall1{{-4, -5}, {4, -5}}, wall2{{5, -4}, {5, 4}};
  const PlanarPose expected = wall1.pose().inverse() * wall2.pose();
  const Eigen::Vector2d world_difference = wall2.midpoint() - wall1.midpoint();
  relslam::test::SeededRandom random(11);
  double raw_spread = 0, min_raw_angle = kPi, max_raw_angle = -kPi;
  PlanarPose first_raw;
  for (int i = 0, drawn = 0; i < 50; ++drawn) {
    ASSERT_LT(drawn, 10000) << "too few poses see both walls";
    const PlanarPose robot = PlanarPose::from(random.uniform(-3, 3), random.uniform(-3, 3), random.uniform(-kPi, kPi));
    if (!both_in_view(robot, wall1, wall2)) continue;
    const PlaneObject seen1 = wall1.transformed(robot.inverse()), seen2 = wall2.transformed(robot.inverse());
    const PlanarPose offset = plane_offset(seen1, seen2);
    EXPECT_LT((offset.translation - expected.translation).norm(), kExact) << "pose " << i;
    EXPECT_NEAR(wrap_angle(offset.heading - expected.heading), 0, kExact) << "pose " << i;
    // Without Rule 3 the difference is translation-invariant only: it turns with the robot.
    const PlanarPose raw = plane_offset(seen1, seen2, false);
    EXPECT_LT((raw.translation - planar_rotation(-robot.heading) * world_difference).norm(), kExact) << "pose " << i;
    EXPECT_NEAR(wrap_angle(raw.heading - expected.heading), 0, kExact) << "pose " << i;  // the angle needs no turn
    if (i == 0) first_raw = raw;
    raw_spread = std::max(raw_spread, (raw.translation - first_raw.translation).norm());
    const double raw_angle = std::atan2(raw.translation.y(), raw.translation.x());
    min_raw_angle = std::min(min_raw_angle, raw_angle);
    max_raw_angle = std::max(max_raw_angle, raw_angle);
    ++i;
  }
  EXPECT_GT(raw_spread, 1.0);                     // |m₂ − m₁| = 5√2: a turn of 0.15 rad moves it 1
  EXPECT_GT(max_raw_angle - min_raw_angle, 0.5);  // radians; measured 1.65
}

// Fig 66's other half: at one heading the raw difference is the same from every position (it
// is translation-invariant), so what Rule 3 adds is the rotation.
TEST(PlaneOffset, RawDifferenceIsTheSameFromEveryPositionAtOneHeading) {
  const PlaneObject wall1{{-4, -5}, {4, -5}}, wall2{{5, -4}, {5, 4}};
  relslam::test::SeededRandom random(12);
  const double heading = -kPi / 4;
  const PlanarPose first = plane_offset(wall1.transformed(PlanarPose::from(0, 0, heading).inverse()),
                                        wall2.transformed(PlanarPose::from(0, 0, heading).inverse()), false);
  for (int i = 0; i < 50; ++i) {
    const PlanarPose robot = PlanarPose::from(random.uniform(-3, 3), random.uniform(-3, 3), heading);
    const PlanarPose raw = plane_offset(wall1.transformed(robot.inverse()), wall2.transformed(robot.inverse()), false);
    EXPECT_LT((raw.translation - first.translation).norm(), kExact) << "pose " << i;
    EXPECT_NEAR(wrap_angle(raw.heading - first.heading), 0, kExact) << "pose " << i;
  }
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
