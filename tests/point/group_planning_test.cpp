#include "relslam/point/group_planning.hpp"

#include "map_feed.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace relslam::point {
namespace {

// What GroupCreation tells the planner about a level.
LevelContext context(const MapFeed& feed, GroupLevel level, const PointSlamOptions& options, bool level_mapped) {
  LevelContext c;
  c.level = level;
  c.options = level == GroupLevel::Temporary ? &options.temporary_group : &options.final_group;
  c.ungrouped = level == GroupLevel::Temporary ? &feed.map.temporary_list : &feed.map.final_list;
  c.level_mapped = level_mapped;
  c.lowest = level == GroupLevel::Temporary;
  c.first_iteration = feed.map.first_iteration;
  return c;
}

// Points some earlier group mapped (at their true positions) and took off the ungrouped lists.
void map_points(MapFeed& feed, const std::vector<PointId>& ids) {
  for (PointId id : ids) {
    feed.place(id);
    feed.map.temporary_list.remove(id);
    feed.map.final_list.remove(id);
  }
}

std::set<PointId> as_set(const std::vector<PointId>& ids) { return {ids.begin(), ids.end()}; }

void expect_valid_basis(const GroupPlan& plan) {
  const std::set<int> basis(plan.basis.begin(), plan.basis.end());
  EXPECT_EQ(basis.size(), 3u);
  for (int b : basis) {
    EXPECT_GE(b, 0);
    EXPECT_LT(b, static_cast<int>(plan.members.size()));
  }
}

TEST(GroupPlanner, RootPlanTakesEveryWaitingPointSeenOftenEnough) {
  MapFeed feed;
  const auto ids = feed.add_landmarks(12, 0, 30);
  const PointId grouped = feed.add_landmarks(1, 0, 30)[0];
  const PointId rare = feed.add_landmarks(1, 4, 30)[0];  // 7 sightings in [0, 10]; 8 are needed
  feed.feed_to(10);
  feed.map.temporary_list.remove(grouped);  // grouped at this level already
  const PointSlamOptions options;
  GroupPlanner planner;
  const PlanOutcome outcome = planner.plan(ids[0], 0, 10, context(feed, GroupLevel::Temporary, options, false),
                                           feed.map.points, feed.map.charting, options);
  ASSERT_TRUE(outcome.plan);
  const GroupPlan& plan = *outcome.plan;
  EXPECT_TRUE(plan.root());
  EXPECT_EQ(plan.registration, Registration::FirstObservations) << "no point is mapped and c0 is the first iteration";
  EXPECT_EQ(as_set(plan.members), as_set(ids))
      << "neither the grouped point " << grouped << " nor the rare one " << rare;
  EXPECT_EQ(plan.anchor, std::vector<bool>(12, false));
  EXPECT_TRUE(outcome.dynamic.empty());
  EXPECT_EQ(outcome.comparisons, 0) << "temporary groups are not binned";
  expect_valid_basis(plan);
}

TEST(GroupPlanner, NoPlanWhenTheCandidateIsSeenTooRarelyInItsWindow) {
  MapFeed feed;
  feed.add_landmarks(12, 0, 30);
  const PointId brief = feed.add_landmarks(1, 0, 3)[0];  // 4 sightings in [0, 10]
  feed.feed_to(10);
  const PointSlamOptions options;
  GroupPlanner planner;
  EXPECT_FALSE(planner
                   .plan(brief, 0, 10, context(feed, GroupLevel::Temporary, options, false), feed.map.points,
                         feed.map.charting, options)
                   .plan);
}

TEST(GroupPlanner, AnchorsAreTheMostSeenMappedPointsUpToPrevMaxThenTheNewPoints) {
  MapFeed feed;
  const auto full = feed.add_landmarks(8, 0, 40);   // 21 sightings in [c0 - B, c0 + A] = [10, 30]
  const auto part = feed.add_landmarks(4, 12, 40);  // 19 there
  const PointId fresh = feed.add_landmarks(1, 20, 40)[0];
  feed.feed_to(30);
  map_points(feed, full);
  map_points(feed, part);
  PointSlamOptions options;
  options.temporary_group.prev_max = 10;
  GroupPlanner planner;
  const PlanOutcome outcome = planner.plan(fresh, 20, 30, context(feed, GroupLevel::Temporary, options, true),
                                           feed.map.points, feed.map.charting, options);
  ASSERT_TRUE(outcome.plan);
  const GroupPlan& plan = *outcome.plan;
  EXPECT_EQ(plan.registration, Registration::Anchors);
  ASSERT_EQ(plan.members.size(), 11u);
  EXPECT_EQ(as_set({plan.members.begin(), plan.members.begin() + 8}), as_set(full)) << "most seen first";
  for (int i = 8; i < 10; ++i) EXPECT_TRUE(as_set(part).count(plan.members[i])) << "member " << i;
  EXPECT_EQ(plan.members[10], fresh);
  std::vector<bool> anchors(11, true);
  anchors[10] = false;
  EXPECT_EQ(plan.anchor, anchors);
  expect_valid_basis(plan);
}

TEST(GroupPlanner, TooFewMappedPointsGiveNoPlanUnlessAProvisionalRootIsAllowed) {
  MapFeed feed;
  const auto mapped = feed.add_landmarks(3, 0, 40);  // prev_min is 6
  const auto fresh = feed.add_landmarks(6, 20, 40);
  feed.feed_to(30);
  map_points(feed, mapped);
  PointSlamOptions options;
  GroupPlanner planner;
  auto plan = [&] {
    return planner.plan(fresh[0], 20, 30, context(feed, GroupLevel::Temporary, options, true), feed.map.points,
                        feed.map.charting, options);
  };
  EXPECT_FALSE(plan().plan) << "the thesis's algorithm cannot place a group here";
  options.provisional_root = true;
  const PlanOutcome outcome = plan();
  ASSERT_TRUE(outcome.plan);
  EXPECT_EQ(outcome.plan->registration, Registration::WorldPositions);
  EXPECT_EQ(outcome.plan->members.size(), 9u);
}

TEST(GroupPlanner, BinningLeavesOutTheMovingPointAndReportsIt) {
  MapFeed feed;
  const auto statics = feed.add_landmarks(12, 0, 60);
  const PointId mover = feed.add_landmark(
      [](int k) { return Eigen::Vector3d(-3.0 + 3.0 * std::sin(k / 5.0), 0.0, 40.0 + 3.0 * std::cos(k / 8.0)); }, 0,
      60);
  feed.feed_to(60);
  const PointSlamOptions options;
  GroupPlanner planner;
  const PlanOutcome outcome = planner.plan(statics[0], 0, 60, context(feed, GroupLevel::Final, options, false),
                                           feed.map.points, feed.map.charting, options);
  EXPECT_EQ(outcome.dynamic, std::vector<PointId>{mover});
  EXPECT_GT(outcome.comparisons, 0);
  ASSERT_TRUE(outcome.plan);
  EXPECT_EQ(outcome.plan->registration, Registration::FirstObservations);
  EXPECT_EQ(as_set(outcome.plan->members), as_set(statics));
  EXPECT_EQ(outcome.plan->anchor.size(), outcome.plan->members.size());
}

TEST(GroupPlanner, CollinearPointsGiveNoBasisAndNoPlan) {
  MapFeed feed;
  std::vector<PointId> ids;
  for (int i = 0; i < 12; ++i)
    ids.push_back(feed.add_landmark(Eigen::Vector3d(-10.0 + 2.0 * i, 1.0, 25.0 + 3.0 * i), 0, 30));
  feed.feed_to(10);
  const PointSlamOptions options;
  GroupPlanner planner;
  EXPECT_FALSE(planner
                   .plan(ids[0], 0, 10, context(feed, GroupLevel::Temporary, options, false), feed.map.points,
                         feed.map.charting, options)
                   .plan)
      << "three points on a line fix no frame (thesis 6.5.4)";
}

TEST(GroupPlanner, Level3PlanSeedsOnThreeMappedPointsAndKeepsThoseThatAddObservations) {
  MapFeed feed;
  const PointId c = feed.add_landmarks(1, 0, 20)[0];
  const auto full = feed.add_landmarks(4, 0, 20);              // seen in all of c's run
  const PointId short_lived = feed.add_landmarks(1, 0, 5)[0];  // would cut the usable iterations to 6
  feed.feed_to(25);
  map_points(feed, full);
  map_points(feed, {short_lived});
  PointSlamOptions options;
  options.level3.enabled = true;
  GroupPlanner planner;
  const PlanOutcome outcome = planner.plan_level3(c, 25, feed.map.points, feed.map.charting, options);
  ASSERT_TRUE(outcome.plan);
  const GroupPlan& plan = *outcome.plan;
  EXPECT_EQ(plan.registration, Registration::Anchors);
  ASSERT_EQ(plan.members.size(), 5u) << "21 iterations x 5 members beat 6 x 6";
  EXPECT_EQ(plan.members[0], c);
  EXPECT_EQ(as_set({plan.members.begin() + 1, plan.members.end()}), as_set(full));
  EXPECT_EQ(plan.anchor, (std::vector<bool>{false, true, true, true, true}));
  expect_valid_basis(plan);
}

TEST(GroupPlanner, Level3PlanNeedsThreeMappedPointsInTheRun) {
  MapFeed feed;
  const PointId c = feed.add_landmarks(1, 0, 20)[0];
  const auto mapped = feed.add_landmarks(2, 0, 20);
  feed.add_landmarks(6, 0, 20);  // seen, but not mapped
  feed.feed_to(25);
  map_points(feed, mapped);
  PointSlamOptions options;
  options.level3.enabled = true;
  GroupPlanner planner;
  EXPECT_FALSE(planner.plan_level3(c, 25, feed.map.points, feed.map.charting, options).plan);
}

}  // namespace
}  // namespace relslam::point
