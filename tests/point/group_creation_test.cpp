#include "relslam/point/group_creation.hpp"

#include "map_feed.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace relslam::point {
namespace {

// Noise-free sightings: what is left is rounding in the basis transforms and RltICP on
// coordinates of tens of units.
constexpr double kExact = 1e-9;

void expect_at_truth(const MapFeed& feed, const std::vector<PointId>& ids) {
  for (PointId id : ids) {
    const RltPoint& p = feed.map.points[id];
    ASSERT_TRUE(p.has_global) << "point " << id;
    EXPECT_LT((p.global - feed.truth(id, 0)).norm(), kExact) << "point " << id;
  }
}

TEST(GroupCreation, NoGroupBeforeTheLookAheadHasPassed) {
  MapFeed feed;
  feed.add_landmarks(12, 0, 30);
  feed.feed_to(9);
  GroupCreation creation;
  const CreationReport report = creation.create_groups(feed.map, 9, PointSlamOptions{});
  EXPECT_EQ(report.groups_created, 0);
  EXPECT_TRUE(feed.map.groups.empty());
  EXPECT_EQ(feed.map.temporary_list.size(), 12u);
}

TEST(GroupCreation, RootTemporaryGroupMapsNoiseFreePointsAtTheirTruePositions) {
  MapFeed feed;
  const auto ids = feed.add_landmarks(12, 0, 30);
  feed.feed_to(10);
  GroupCreation creation;
  const CreationReport report = creation.create_groups(feed.map, 10, PointSlamOptions{});
  EXPECT_EQ(report.groups_created, 1);
  ASSERT_EQ(feed.map.groups.size(), 1u);
  const RltGroup& group = feed.map.groups[0];
  EXPECT_EQ(group.level(), GroupLevel::Temporary);
  EXPECT_EQ(group.registration(), Registration::FirstObservations) << "the first group roots the map (thesis 6.3.3)";
  EXPECT_EQ(group.members().size(), 12u);
  EXPECT_EQ(group.iterations_used(), 11) << "computed over [c0, k] as soon as it is built";
  expect_at_truth(feed, ids);
  for (PointId id : ids) {
    EXPECT_EQ(feed.map.points[id].owner, 0);
    EXPECT_TRUE(feed.map.points[id].temporary_grouped);
    EXPECT_FALSE(feed.map.points[id].final_grouped);
  }
  EXPECT_TRUE(feed.map.temporary_list.empty());
  EXPECT_EQ(feed.map.final_list.size(), 12u) << "still waiting for the final look-ahead";
  EXPECT_EQ(feed.map.stats.created, 1);
  EXPECT_EQ(feed.map.stats.temporary_alive, 1);
  EXPECT_EQ(feed.map.stats.alive_members, 12);
  EXPECT_EQ(feed.map.take_changed().size(), 12u);
}

TEST(GroupCreation, PointFirstSeenLaterGetsItsOwnGroupAnchoredOnTheMappedPoints) {
  MapFeed feed;
  const auto early = feed.add_landmarks(12, 0, 30);
  // Six sightings in [0, 10] are fewer than look_ahead - accuracy_reduction = 8: not in the root.
  const PointId late = feed.add_landmarks(1, 5, 30)[0];
  feed.feed_to(15);
  GroupCreation creation;
  const PointSlamOptions options;
  creation.create_groups(feed.map, 10, options);
  ASSERT_EQ(feed.map.groups.size(), 1u);
  EXPECT_FALSE(feed.map.points[late].has_global);
  EXPECT_EQ(creation.create_groups(feed.map, 14, options).groups_created, 0) << "its look-ahead ends at 5 + 10";
  EXPECT_EQ(creation.create_groups(feed.map, 15, options).groups_created, 1);
  ASSERT_EQ(feed.map.groups.size(), 2u);
  const RltGroup& group = feed.map.groups[1];
  EXPECT_EQ(group.registration(), Registration::Anchors);
  EXPECT_EQ(group.members().size(), 13u);
  for (std::size_t i = 0; i < group.members().size(); ++i)
    EXPECT_EQ(group.anchor(static_cast<int>(i)), group.members()[i] != late) << "member " << group.members()[i];
  EXPECT_EQ(feed.map.points[late].owner, 1);
  EXPECT_EQ(feed.map.points[early[0]].owner, 0) << "anchors keep their owner";
  expect_at_truth(feed, {late});
}

TEST(GroupCreation, FinalGroupTakesThePointsOverAndTheRedundantTemporaryGroupIsRetired) {
  MapFeed feed;
  const auto ids = feed.add_landmarks(12, 0, 80);
  feed.feed_to(80);
  GroupCreation creation;
  const PointSlamOptions options;
  for (int k = 10; k <= 60; ++k) creation.create_groups(feed.map, k, options);
  ASSERT_EQ(feed.map.groups.size(), 2u);
  const RltGroup& final_group = feed.map.groups[1];
  EXPECT_EQ(final_group.level(), GroupLevel::Final);
  EXPECT_EQ(final_group.iterations_used(), 61);
  EXPECT_EQ(feed.map.stats.final_created, 1);
  for (PointId id : ids) {
    EXPECT_EQ(feed.map.points[id].owner, 1) << "final groups take their new members (thesis 6.4)";
    EXPECT_TRUE(feed.map.points[id].final_grouped);
  }
  expect_at_truth(feed, ids);

  // Reviewed once the final look-ahead after it has passed: 10 + 60 + 10.
  creation.retire_redundant_temporary_groups(feed.map, 79, options);
  EXPECT_TRUE(feed.map.groups[0].alive());
  creation.retire_redundant_temporary_groups(feed.map, 80, options);
  EXPECT_FALSE(feed.map.groups[0].alive()) << "it owns none of its members: it maps nothing";
  EXPECT_TRUE(feed.map.groups[1].alive());
  EXPECT_EQ(feed.map.stats.alive, 1);
  EXPECT_EQ(feed.map.stats.temporary_alive, 0);
  EXPECT_EQ(feed.map.stats.alive_members, 12);
  for (PointId id : ids) {
    ASSERT_EQ(feed.map.points[id].groups.size(), 1u);
    EXPECT_EQ(feed.map.points[id].groups[0].group, 1);
  }
}

TEST(GroupCreation, FinalGroupLeavesOutAMovingPointAndFlagsItDynamic) {
  MapFeed feed;
  const auto statics = feed.add_landmarks(12, 0, 60);
  const PointId mover = feed.add_landmark(
      [](int k) {
        return Eigen::Vector3d(4.0 + 3.0 * std::sin(k / 6.0), 0.5 * std::sin(k / 9.0), 35.0 + 3.0 * std::cos(k / 7.0));
      },
      0, 60);
  feed.feed_to(60);
  GroupCreation creation;
  const PointSlamOptions options;
  creation.create_groups(feed.map, 10, options);  // temporary groups do not bin: the mover is in
  const CreationReport report = creation.create_groups(feed.map, 60, options);
  EXPECT_EQ(report.groups_created, 1);
  EXPECT_EQ(report.dynamic_flagged, 1);
  EXPECT_GT(report.binning_comparisons, 0);
  EXPECT_EQ(feed.map.stats.dynamic_points, 1);
  const RltPoint& m = feed.map.points[mover];
  EXPECT_TRUE(m.dynamic);
  EXPECT_FALSE(m.on_map());
  EXPECT_FALSE(feed.map.final_list.contains(mover));
  EXPECT_FALSE(feed.map.global_index->contains(mover));
  const RltGroup& final_group = feed.map.groups.back();
  EXPECT_EQ(final_group.level(), GroupLevel::Final);
  EXPECT_EQ(final_group.members().size(), 12u);
  expect_at_truth(feed, statics);
}

TEST(GroupCreation, Level3GroupFormsOnlyOnceAPointHasLeftTheView) {
  PointSlamOptions options;
  options.level3.enabled = true;
  MapFeed feed(options);
  const auto ids = feed.add_landmarks(12, 0, 30);
  feed.feed_to(34);
  GroupCreation creation;
  for (PointId id : ids) creation.add_point(id, options);
  creation.create_groups(feed.map, 10, options);
  // Last seen at 30: still in view while unseen for no more than level3.gap = 3 iterations.
  EXPECT_EQ(creation.create_groups(feed.map, 33, options).groups_created, 0);
  EXPECT_EQ(creation.create_groups(feed.map, 34, options).groups_created, 12) << "each point gets its one chance";
  EXPECT_EQ(feed.map.stats.level3_created, 12);
  for (PointId id : ids) {
    const RltPoint& p = feed.map.points[id];
    EXPECT_TRUE(p.level3_grouped);
    ASSERT_GE(p.owner, 1);
    EXPECT_EQ(feed.map.groups[p.owner].level(), GroupLevel::Level3);
  }
  expect_at_truth(feed, ids);
  EXPECT_EQ(creation.create_groups(feed.map, 35, options).groups_created, 0) << "none is waiting any more";
}

TEST(MarkDynamic, FlaggedPointLeavesListsAndIndexAndRetiresTheGroupsWithItInTheirBasis) {
  MapFeed feed;
  feed.add_landmarks(12, 0, 30);
  feed.feed_to(10);
  GroupCreation creation;
  creation.create_groups(feed.map, 10, PointSlamOptions{});
  ASSERT_EQ(feed.map.groups.size(), 1u);
  const RltGroup& group = feed.map.groups[0];
  PointId basis_point = kNone, other = kNone;
  for (int i = 0; i < static_cast<int>(group.members().size()); ++i) {
    const bool in_basis = std::find(group.basis().begin(), group.basis().end(), i) != group.basis().end();
    (in_basis ? basis_point : other) = group.members()[i];
  }
  feed.feed_to(11);  // the next iteration: its changes are listed afresh
  feed.map.take_changed();

  EXPECT_TRUE(mark_dynamic(feed.map, other));
  EXPECT_FALSE(mark_dynamic(feed.map, other)) << "flagged once";
  EXPECT_TRUE(feed.map.points[other].dynamic);
  EXPECT_FALSE(feed.map.final_list.contains(other));
  EXPECT_FALSE(feed.map.global_index->contains(other));
  EXPECT_EQ(feed.map.take_changed(), std::vector<PointId>{other});
  EXPECT_TRUE(group.alive()) << "its frame does not depend on that point";

  EXPECT_TRUE(mark_dynamic(feed.map, basis_point));
  EXPECT_FALSE(group.alive()) << "a moving basis point leaves the group no consistent frame";
  EXPECT_EQ(feed.map.stats.alive, 0);
  EXPECT_EQ(feed.map.stats.alive_members, 0);
  EXPECT_EQ(feed.map.stats.dynamic_points, 2);
  for (PointId id : group.members()) EXPECT_TRUE(feed.map.points[id].groups.empty());
}

}  // namespace
}  // namespace relslam::point
