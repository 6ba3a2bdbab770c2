// Every spatial index variant against brute force on random data.
#include "relslam/spatial/ovlp_quadtree.hpp"
#include "relslam/spatial/global_index.hpp"
#include "relslam/spatial/incremental_ovlp_quadtree.hpp"
#include "relslam/spatial/local_index.hpp"
#include "relslam/spatial/make_local_index.hpp"

#include "seeded_random.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace relslam::spatial {
namespace {

bool within_linf_xz(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double r) {
  return std::abs(a.x() - b.x()) <= r && std::abs(a.z() - b.z()) <= r;
}

class LocalIndexVariants : public ::testing::TestWithParam<std::pair<LocalIndexKind, double>> {};

TEST_P(LocalIndexVariants, QueryContainsEveryPointWithinTheRadius) {
  const auto [kind, cell] = GetParam();
  constexpr double kRadius = 1.2;
  const auto index = make_local_index(kind, cell, kRadius);
  test::SeededRandom rng(501);
  for (int trial = 0; trial < 4; ++trial) {
    std::vector<IndexedPoint> points;
    for (int i = 0; i < 800; ++i)
      points.push_back({i, {rng.uniform(-100, 100), rng.uniform(-5, 5), rng.uniform(0, 100)}});
    // Some close clusters so queries find several candidates.
    for (int i = 0; i < 100; ++i)
      points.push_back({800 + i, points[i].p + 0.5 * Eigen::Vector3d(rng.gaussian(), rng.gaussian(), rng.gaussian())});
    index->build(points);
    for (int q = 0; q < 2000; ++q) {
      const Eigen::Vector3d query =
          q % 2 ? Eigen::Vector3d(rng.uniform(-110, 110), rng.uniform(-6, 6), rng.uniform(-10, 110))
                : Eigen::Vector3d(points[q % points.size()].p +
                                  Eigen::Vector3d(rng.gaussian(), 0.3 * rng.gaussian(), rng.gaussian()));
      std::set<int> found;
      for (const IndexedPoint& e : index->query(query)) found.insert(e.id);
      for (const IndexedPoint& p : points)
        if ((p.p - query).norm() <= kRadius) {
          ASSERT_TRUE(found.count(p.id)) << to_string(kind) << " missed point " << p.id;
        }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllKinds, LocalIndexVariants,
                         ::testing::Values(std::pair{LocalIndexKind::Quadtree, 5.0},
                                           std::pair{LocalIndexKind::Quadtree, 1.5},
                                           std::pair{LocalIndexKind::Octree, 1.5},
                                           std::pair{LocalIndexKind::KdTree, 0.0}));

TEST(OVLPQuadTree, HoldsEveryPointWithinTheOverlapOnXAndZ) {
  test::SeededRandom rng(503);
  OVLPQuadTree tree(5.0, 1.2);
  std::vector<IndexedPoint> points;
  for (int i = 0; i < 500; ++i) points.push_back({i, {rng.uniform(-50, 50), rng.uniform(-5, 5), rng.uniform(0, 50)}});
  tree.build(points);
  for (int q = 0; q < 1000; ++q) {
    const Eigen::Vector3d query(rng.uniform(-55, 55), 0, rng.uniform(-5, 55));
    std::set<int> found;
    for (const IndexedPoint& e : tree.query(query)) found.insert(e.id);
    for (const IndexedPoint& p : points)
      if (within_linf_xz(p.p, query, 1.2)) {
        ASSERT_TRUE(found.count(p.id));
      }
  }
}

TEST(OVLPQuadTree, EmptyTreeAnswersNothing) {
  OVLPQuadTree tree(5, 1);
  tree.build({});
  EXPECT_TRUE(tree.query({0, 0, 0}).empty());
}

TEST(KdTreeIndex, ReturnsExactlyThePointsWithinTheRadius) {
  test::SeededRandom rng(504);
  auto index = make_local_index(LocalIndexKind::KdTree, 0, 2.0);
  std::vector<IndexedPoint> points;
  for (int i = 0; i < 300; ++i)
    points.push_back({i, {rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-10, 10)}});
  index->build(points);
  for (int q = 0; q < 200; ++q) {
    const Eigen::Vector3d query(rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-10, 10));
    std::set<int> found, expected;
    for (const IndexedPoint& e : index->query(query)) found.insert(e.id);
    for (const IndexedPoint& p : points)
      if ((p.p - query).norm() <= 2.0) expected.insert(p.id);
    ASSERT_EQ(found, expected);
  }
}

class GlobalIndexVariants : public ::testing::TestWithParam<GlobalIndexKind> {};

TEST_P(GlobalIndexVariants, InsertsMovesAndRemovesLikeBruteForce) {
  test::SeededRandom rng(502);
  const auto tree = make_global_index(GetParam(), 4.0, 2.0);
  std::vector<Eigen::Vector3d> position(300);
  std::vector<bool> stored(300, false);
  for (int step = 0; step < 5000; ++step) {
    const int id = static_cast<int>(rng.below(300));
    if (rng.uniform() < 0.7) {
      position[id] = {rng.uniform(-60, 60), rng.uniform(-5, 5), rng.uniform(-60, 60)};
      tree->place(id, position[id]);
      stored[id] = true;
    } else {
      tree->remove(id);
      stored[id] = false;
    }
    if (step % 50 != 0) continue;
    tree->prepare();
    EXPECT_EQ(tree->size(), static_cast<std::size_t>(std::count(stored.begin(), stored.end(), true)));
    for (int q = 0; q < 100; ++q) {
      const Eigen::Vector3d query(rng.uniform(-65, 65), 0, rng.uniform(-65, 65));
      const auto found = tree->query(query);
      for (int i = 0; i < 300; ++i) {
        const bool listed = std::find(found.begin(), found.end(), i) != found.end();
        if (stored[i] && within_linf_xz(position[i], query, 2.0)) {
          ASSERT_TRUE(listed) << to_string(GetParam()) << " id " << i;
        }
        if (!stored[i]) {
          ASSERT_FALSE(listed) << "removed id " << i << " still listed";
        }
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(BothKinds, GlobalIndexVariants,
                         ::testing::Values(GlobalIndexKind::Incremental, GlobalIndexKind::Rebuilt));

TEST(SpatialIndexes, OverlapLargerThanTheCellIsABug) {
  EXPECT_THROW(IncrementalOVLPQuadTree(1.0, 2.0), std::logic_error);
  EXPECT_THROW(OVLPQuadTree(1.0, 2.0), std::logic_error);
  EXPECT_THROW(OVLPOctree(1.0, 2.0), std::logic_error);
}

TEST(SpatialIndexes, NamesRoundTrip) {
  for (LocalIndexKind k : {LocalIndexKind::Quadtree, LocalIndexKind::Octree, LocalIndexKind::KdTree})
    EXPECT_EQ(parse_local_index(to_string(k)), k);
  for (GlobalIndexKind k : {GlobalIndexKind::Incremental, GlobalIndexKind::Rebuilt})
    EXPECT_EQ(parse_global_index(to_string(k)), k);
}

}  // namespace
}  // namespace relslam::spatial
