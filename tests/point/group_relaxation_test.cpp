// The global relaxation problem as built from and written back to an RltMap, on
// noise-free maps from MapFeed: no solver here (tests/relax/ has the Ceres one).
#include "relslam/point/group_relaxation.hpp"

#include "map_feed.hpp"
#include "relslam/point/group_creation.hpp"

#include <gtest/gtest.h>

namespace relslam::point {
namespace {

// Noise-free sightings: rounding in the basis transforms and RltICP on tens of units.
constexpr double kExact = 1e-9;

// Twelve points seen from iteration 0 root the map (group 0); a thirteenth, first seen at
// iteration 5, gets group 1, anchored on them.
struct TwoGroups {
  MapFeed feed;
  std::vector<PointId> early;
  PointId late = kNone;
  TwoGroups() {
    early = feed.add_landmarks(12, 0, 30);
    late = feed.add_landmarks(1, 5, 30)[0];
    feed.feed_to(15);
    GroupCreation creation;
    creation.create_groups(feed.map, 10, PointSlamOptions{});
    creation.create_groups(feed.map, 15, PointSlamOptions{});
  }
};

TEST(BuildRelaxation, FirstObservationsHoldTheMapFrameAndTheRootIsFree) {
  TwoGroups map;
  ASSERT_EQ(map.feed.map.groups.size(), 2u);
  const MapRelaxation r = build_relaxation(map.feed.map, 0.3);
  ASSERT_EQ(r.groups.size(), 3u) << "the first frame's body and the two groups";
  EXPECT_EQ(r.groups[0], kNone);
  EXPECT_TRUE(r.problem.fixed[0]);
  EXPECT_EQ(r.problem.world_T_group[0].translation, Eigen::Vector3d::Zero());
  EXPECT_FALSE(r.problem.fixed[1]) << "twelve first observations hold the frame: the root is free";
  EXPECT_FALSE(r.problem.fixed[2]);
  // One gauge tie per point seen at the first iteration, holding that observation; one tie per
  // anchor shared by the two groups.
  int gauge = 0, shared = 0;
  for (const GroupTie& tie : r.problem.ties) {
    if (tie.a == 0) {
      ++gauge;
      EXPECT_LT(tie.weight, 1.0) << "one observation against an average";
    } else {
      ++shared;
    }
    EXPECT_LT(tie_gap(r.problem, tie), kExact) << "noise-free ties hold at the current registrations";
  }
  EXPECT_EQ(gauge, 12);
  EXPECT_EQ(shared, 12);
}

TEST(ApplyRelaxation, MovesWhatFreeGroupsOwnAndNothingElse) {
  TwoGroups map;
  MapRelaxation r = build_relaxation(map.feed.map, 0.3);
  // The root moved by a known motion; group 1 stays where it is.
  const Rigid3 motion{rotation_about(Eigen::Vector3d::UnitY(), 0.1), Eigen::Vector3d(0.5, 0, -0.2)};
  r.problem.world_T_group[1] = motion * r.problem.world_T_group[1];
  EXPECT_EQ(apply_relaxation(map.feed.map, r), 13) << "twelve owned by the root, one by group 1";
  for (const PointId id : map.early)
    EXPECT_LT((map.feed.map.points[id].global - motion * map.feed.truth(id, 0)).norm(), kExact) << id;
  EXPECT_LT((map.feed.map.points[map.late].global - map.feed.truth(map.late, 0)).norm(), kExact);
}

// relaxation_trigger_gap's question: which points have a tie whose gap, weighted as the solver
// weighs it (one observation's worth), is over a bound. Group 1 moved by 0.5 opens the twelve
// ties it shares with the root by 0.5 each; the first frame's ties stay closed.
TEST(PointsOver, NamesThePointsOfTheOpenTiesWeightedAsTheSolverWeighsThem) {
  TwoGroups map;
  MapRelaxation r = build_relaxation(map.feed.map, 0.3);
  EXPECT_TRUE(points_over(r, 1e-6).empty()) << "noise-free ties are closed";
  r.problem.world_T_group[2].translation += Eigen::Vector3d(0.5, 0, 0);
  double weight = 0;
  for (const GroupTie& tie : r.problem.ties) {
    if (tie.a == 0) {
      EXPECT_LT(tie_gap(r.problem, tie), kExact);
      continue;
    }
    EXPECT_NEAR(tie_gap(r.problem, tie), 0.5, kExact);
    weight = tie.weight;
  }
  ASSERT_GT(weight, 1.0) << "two averages: a tie weighs more than one observation each";
  const std::vector<PointId> open = points_over(r, 0.5 * weight - 1e-6);
  std::vector<PointId> early = map.early;
  std::ranges::sort(early);
  EXPECT_EQ(open, early);
  EXPECT_TRUE(points_over(r, 0.5 * weight + 1e-6).empty()) << "the bound is on the weighted gap";
  EXPECT_EQ(points_over(r, 0.4), early) << "below 0.5 either way";
}

}  // namespace
}  // namespace relslam::point
