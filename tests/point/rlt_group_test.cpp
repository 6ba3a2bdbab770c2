#include "relslam/point/rlt_group.hpp"

#include "seeded_random.hpp"

#include <gtest/gtest.h>
#include <Eigen/Dense>

namespace relslam::point {
namespace {

// Static points seen from a moving viewpoint, noise-free: n iterations, one RltPoint each.
std::vector<RltPoint> observed_points(const std::vector<Eigen::Vector3d>& world, int iterations,
                                      test::SeededRandom& rng, std::vector<Rigid3>* poses) {
  std::vector<RltPoint> points(world.size());
  for (std::size_t i = 0; i < world.size(); ++i) points[i].id = static_cast<PointId>(i);
  for (int k = 0; k < iterations; ++k) {
    const Rigid3 world_T_robot =
        k == 0 ? Rigid3::identity()
               : Rigid3::from(Eigen::Quaterniond(1, 0.1 * rng.gaussian(), 0.1 * rng.gaussian(), 0.1 * rng.gaussian()),
                              {rng.uniform(-5, 5), rng.uniform(-1, 1), rng.uniform(-5, 5)});
    poses->push_back(world_T_robot);
    for (std::size_t i = 0; i < world.size(); ++i) {
      const Point o{world_T_robot.inverse_apply(world[i]), k};
      points[i].observations.push(o);
      points[i].interval.add(k);
      if (k == 0) points[i].first_observation = o;
    }
  }
  return points;
}

std::vector<Eigen::Vector3d> random_world(test::SeededRandom& rng, int n) {
  std::vector<Eigen::Vector3d> world;
  for (int i = 0; i < n; ++i) world.emplace_back(rng.uniform(-40, 40), rng.uniform(-5, 5), rng.uniform(10, 90));
  return world;
}

TEST(RltGroup, NoiseFreeRelativePositionsAreTheTrueBasisCoordinates) {
  test::SeededRandom rng(601);
  const auto world = random_world(rng, 12);
  std::vector<Rigid3> poses;
  const auto points = observed_points(world, 20, rng, &poses);
  std::vector<PointId> members(12);
  for (int i = 0; i < 12; ++i) members[i] = i;
  RltGroup group(0, GroupLevel::Final, 0, 19, members, std::vector<bool>(12, false), {0, 5, 7},
                 Registration::FirstObservations);
  ASSERT_TRUE(group.accumulate(points, 0, 19, 1e-6));
  EXPECT_EQ(group.iterations_used(), 20);
  const auto frame = basis_frame(world[0], world[5], world[7]);
  for (int i = 0; i < 12; ++i) EXPECT_LT((group.relative(i) - (*frame)(world[i])).norm(), 1e-11) << "member " << i;
  EXPECT_FALSE(group.accumulate(points, 0, 19, 1e-6)) << "iterations are used once";
}

TEST(RltGroup, RootRegistrationRecoversTheWorldFromTheFirstObservations) {
  test::SeededRandom rng(602);
  const auto world = random_world(rng, 10);
  std::vector<Rigid3> poses;
  const auto points = observed_points(world, 15, rng, &poses);
  std::vector<PointId> members(10);
  for (int i = 0; i < 10; ++i) members[i] = i;
  RltGroup group(0, GroupLevel::Temporary, 0, 14, members, std::vector<bool>(10, false), {1, 2, 3},
                 Registration::FirstObservations);
  group.accumulate(points, 0, 14, 1e-6);
  const auto world_T_group = group.registration(points, 0);
  ASSERT_TRUE(world_T_group);
  for (int i = 0; i < 10; ++i) EXPECT_LT((*world_T_group * group.relative(i) - world[i]).norm(), 1e-10);
}

TEST(RltGroup, AnchoredRegistrationUsesTheAnchorsMapPositions) {
  test::SeededRandom rng(603);
  const auto world = random_world(rng, 8);
  std::vector<Rigid3> poses;
  auto points = observed_points(world, 10, rng, &poses);
  std::vector<bool> anchor(8, false);
  for (int i = 0; i < 4; ++i) {
    anchor[i] = true;
    points[i].global = world[i];
    points[i].has_global = true;
  }
  std::vector<PointId> members = {0, 1, 2, 3, 4, 5, 6, 7};
  RltGroup group(3, GroupLevel::Final, 0, 9, members, anchor, {0, 4, 6}, Registration::Anchors);
  group.accumulate(points, 0, 9, 1e-6);
  const auto world_T_group = group.registration(points, 0);
  ASSERT_TRUE(world_T_group);
  for (int i = 4; i < 8; ++i) EXPECT_LT((*world_T_group * group.relative(i) - world[i]).norm(), 1e-10);
}

TEST(RltGroup, IterationsWithAMissingMemberAreSkipped) {
  test::SeededRandom rng(604);
  const auto world = random_world(rng, 5);
  std::vector<Rigid3> poses;
  auto points = observed_points(world, 6, rng, &poses);
  RltPoint gappy;
  gappy.id = 5;
  for (int k : {0, 2, 4, 5}) {
    gappy.observations.push({poses[k].inverse_apply(Eigen::Vector3d(1, 2, 30)), k});
    gappy.interval.add(k);
  }
  points.push_back(gappy);
  RltGroup group(0, GroupLevel::Final, 0, 5, {0, 1, 2, 3, 4, 5}, std::vector<bool>(6, false), {0, 1, 2},
                 Registration::FirstObservations);
  group.accumulate(points, 0, 5, 1e-6);
  EXPECT_EQ(group.iterations_used(), 4);
  EXPECT_EQ(group.computed_on().count(0, 5), 4);
  EXPECT_FALSE(group.computed_on().contains(1));
}

}  // namespace
}  // namespace relslam::point
