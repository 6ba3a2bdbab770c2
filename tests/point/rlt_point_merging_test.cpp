#include "relslam/point/rlt_point_merging.hpp"

#include "map_feed.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace relslam::point {
namespace {

// Noise-free sightings: what is left is rounding in the basis transforms and RltICP on
// coordinates of tens of units.
constexpr double kExact = 1e-9;
const Eigen::Vector3d kSpot(5.0, 0.5, 30.0);

// A group over `members` (the first three its basis), built at iteration k as group creation
// builds one: in its members' refs, counted, owning its non-anchors, computed over [c0, k].
GroupId add_group(RltMap& map, int c0, int k, const std::vector<PointId>& members, const std::vector<bool>& anchor) {
  const auto id = static_cast<GroupId>(map.groups.size());
  map.groups.emplace_back(id, GroupLevel::Final, c0, k, members, anchor, std::array<int, 3>{0, 1, 2},
                          Registration::Anchors);
  ++map.stats.alive;
  map.stats.alive_members += static_cast<long long>(members.size());
  for (std::size_t i = 0; i < members.size(); ++i) {
    map.points[members[i]].groups.push_back({id, static_cast<int>(i)});
    if (!anchor[i]) map.points[members[i]].owner = id;
  }
  map.compute(map.groups.back(), c0, k);
  return id;
}

// Four landmarks seen throughout [0, 30]; `older` seen in [0, 10] and the same landmark found
// again in [20, 30] as `newer` (global matching missed it). All on the map at their true places.
struct Revisit {
  MapFeed feed;
  std::vector<PointId> others = feed.add_landmarks(4, 0, 30);
  PointId older = feed.add_landmark(kSpot, 0, 10);
  PointId newer = feed.add_landmark(kSpot, 20, 30);
  Revisit() {
    feed.feed_to(30);
    for (PointId id : others) feed.place(id);
    feed.place(older);
    feed.place(newer);
  }
};

TEST(RltPointMerging, PartnerIsTheClosestOlderMappedPointNeverSeenTogether) {
  MapFeed feed;
  const PointId chosen = feed.add_landmark(kSpot + Eigen::Vector3d(0.3, 0, 0), 0, 10);
  const PointId seen_together = feed.add_landmark(kSpot + Eigen::Vector3d(0.2, 0, 0), 0, 25);
  const PointId farther = feed.add_landmark(kSpot + Eigen::Vector3d(0.5, 0, 0), 0, 10);
  const PointId beyond = feed.add_landmark(kSpot + Eigen::Vector3d(0, 0, 2.5), 0, 10);
  const PointId p = feed.add_landmark(kSpot, 20, 30);
  const PointId younger = feed.add_landmark(kSpot + Eigen::Vector3d(0.1, 0, 0), 22, 30);
  feed.feed_to(30);
  for (PointId id : {chosen, seen_together, farther, beyond, p, younger}) feed.place(id);
  EXPECT_EQ(merge_partner(feed.map, p, 2.0), chosen);
  EXPECT_EQ(merge_partner(feed.map, p, 0.25), kNone) << "the nearer ones were seen with it or are younger";
  EXPECT_EQ(merge_partner(feed.map, chosen, 2.0), kNone) << "only older points are partners";
}

TEST(RltPointMerging, NoPartnerForAPointOffTheMap) {
  Revisit r;
  r.feed.map.points[r.newer].dynamic = true;
  EXPECT_EQ(merge_partner(r.feed.map, r.newer, 2.0), kNone);
  r.feed.map.points[r.newer].dynamic = false;
  EXPECT_EQ(merge_partner(r.feed.map, r.newer, 2.0), r.older);
  r.feed.map.points[r.older].dynamic = true;
  EXPECT_EQ(merge_partner(r.feed.map, r.newer, 2.0), kNone) << "a dynamic point is no partner either";
}

TEST(RltPointMerging, OlderPointTakesEveryObservationAndTheNewerOneLeavesTheMap) {
  Revisit r;
  RltMap& map = r.feed.map;
  const Eigen::Vector3d older_global = map.points[r.older].global;
  map.take_changed();
  r.feed.feed_to(31);  // merging runs in the iteration after
  merge_points(map, r.newer, r.older, 31);

  const RltPoint& older = map.points[r.older];
  ASSERT_EQ(older.observations.size(), 22);
  for (int i = 0; i < older.observations.size(); ++i)
    EXPECT_EQ(older.observations[i].iteration, i <= 10 ? i : i + 9) << "in iteration order";
  EXPECT_EQ(older.interval.count(0, 30), 22);
  EXPECT_EQ(older.global, older_global) << "the older point keeps its map position";
  for (int k = 20; k <= 30; ++k) {
    const auto& seen = map.charting.at(k);
    EXPECT_NE(std::find(seen.begin(), seen.end(), r.older), seen.end()) << "iteration " << k;
    EXPECT_EQ(std::find(seen.begin(), seen.end(), r.newer), seen.end()) << "iteration " << k;
  }
  const RltPoint& newer = map.points[r.newer];
  EXPECT_TRUE(newer.merged);
  EXPECT_EQ(newer.merged_into, r.older);
  EXPECT_FALSE(newer.on_map());
  EXPECT_FALSE(map.global_index->contains(r.newer));
  EXPECT_FALSE(map.temporary_list.contains(r.newer));
  EXPECT_FALSE(map.final_list.contains(r.newer));
  EXPECT_EQ(map.stats.merged_points, 1);
  EXPECT_EQ(map.take_changed(), std::vector<PointId>{r.newer});
}

TEST(RltPointMerging, OlderPointsGroupsAccumulateTheCopiedIterations) {
  Revisit r;
  RltMap& map = r.feed.map;
  const GroupId g = add_group(map, 0, 10, {r.others[0], r.others[1], r.others[2], r.older}, {true, true, true, false});
  ASSERT_EQ(map.groups[g].iterations_used(), 11);
  merge_points(map, r.newer, r.older, 30);
  EXPECT_EQ(map.groups[g].iterations_used(), 22) << "[0, 10] and the copied [20, 30]";
  EXPECT_LT((map.points[r.older].global - kSpot).norm(), kExact) << "noise-free: the average stays exact";
}

TEST(RltPointMerging, GroupsOfTheNewerPointHoldTheOlderOneAsAnAnchor) {
  Revisit r;
  RltMap& map = r.feed.map;
  const GroupId g = add_group(map, 20, 30, {r.others[0], r.others[1], r.others[2], r.newer}, {true, true, true, false});
  const GroupId both = add_group(map, 0, 30, {r.others[0], r.others[1], r.others[3], r.older, r.newer},
                                 {true, true, true, false, false});
  const int used = map.groups[g].iterations_used();
  merge_points(map, r.newer, r.older, 30);

  const RltGroup& group = map.groups[g];
  EXPECT_TRUE(group.alive());
  EXPECT_EQ(group.members()[3], r.older);
  EXPECT_TRUE(group.anchor(3)) << "the older point keeps its own owner and map position";
  EXPECT_EQ(group.iterations_used(), used) << "the same observations: its sums stay valid";
  const auto& refs = map.points[r.older].groups;
  EXPECT_TRUE(
      std::any_of(refs.begin(), refs.end(), [&](const RltGroupRef& ref) { return ref.group == g && ref.member == 3; }));
  EXPECT_TRUE(map.points[r.newer].groups.empty());

  EXPECT_FALSE(map.groups[both].alive()) << "a group holding both could never be computed consistently";
  EXPECT_EQ(map.stats.alive, 1);
  EXPECT_EQ(map.stats.alive_members, 4);
}

TEST(RltPointMerging, EachCheckRunsOnceWhenItIsDue) {
  Revisit r;
  RltMap& map = r.feed.map;
  RltPointMerging merging;
  merging.schedule(r.others[3], 25);  // no partner: dropped, never retried
  merging.schedule(r.newer, 25);
  EXPECT_EQ(merging.merge_due(map, 24, 2.0), 0);
  EXPECT_FALSE(map.points[r.newer].merged);
  EXPECT_EQ(merging.merge_due(map, 25, 2.0), 1);
  EXPECT_TRUE(map.points[r.newer].merged);
  EXPECT_EQ(merging.merge_due(map, 26, 2.0), 0);
  EXPECT_EQ(map.stats.merged_points, 1);
}

}  // namespace
}  // namespace relslam::point
