#include "relslam/spatial/incremental_ovlp_quadtree.hpp"
#include "relslam/spatial/ovlp_quadtree.hpp"

#include "relslam/sim/random.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace relslam::spatial {
namespace {

bool within_linf(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double r) {
  return std::abs(a.x() - b.x()) <= r && std::abs(a.z() - b.z()) <= r;
}

TEST(OVLPQuadTree, QueryReturnsEveryPointWithinTheOverlap) {
  sim::RandomSequence rng(501, sim::Stream::Field);
  for (double cell : {5.0, 1.5}) {
    OVLPQuadTree tree(cell, 1.2);
    for (int trial = 0; trial < 5; ++trial) {
      std::vector<IndexedPoint> points;
      for (int i = 0; i < 800; ++i) points.push_back({i, {rng.uniform(-100, 100), rng.uniform(-5, 5), rng.uniform(0, 100)}});
      tree.build(points);
      for (int q = 0; q < 2000; ++q) {
        const Eigen::Vector3d query(rng.uniform(-110, 110), 0, rng.uniform(-10, 110));
        std::set<int> found;
        for (const IndexedPoint& e : tree.query(query)) found.insert(e.id);
        for (const IndexedPoint& p : points)
          if (within_linf(p.p, query, 1.2)) {
            ASSERT_TRUE(found.count(p.id)) << "cell " << cell << " point " << p.id;
          }
      }
    }
  }
}

TEST(OVLPQuadTree, EmptyTreeAnswersNothing) {
  OVLPQuadTree tree(5, 1);
  tree.build({});
  EXPECT_TRUE(tree.query({0, 0, 0}).empty());
}

TEST(IncrementalOVLPQuadTree, InsertsMovesAndRemovesLikeBruteForce) {
  sim::RandomSequence rng(502, sim::Stream::Field);
  IncrementalOVLPQuadTree tree(4.0, 2.0);
  std::vector<Eigen::Vector3d> position(300);
  std::vector<bool> stored(300, false);
  for (int step = 0; step < 5000; ++step) {
    const int id = static_cast<int>(rng.below(300));
    const double op = rng.uniform();
    if (op < 0.7) {
      position[id] = {rng.uniform(-60, 60), rng.uniform(-5, 5), rng.uniform(-60, 60)};
      tree.place(id, position[id]);
      stored[id] = true;
    } else {
      tree.remove(id);
      stored[id] = false;
    }
    if (step % 50 != 0) continue;
    EXPECT_EQ(tree.size(), static_cast<std::size_t>(std::count(stored.begin(), stored.end(), true)));
    for (int q = 0; q < 100; ++q) {
      const Eigen::Vector3d query(rng.uniform(-65, 65), 0, rng.uniform(-65, 65));
      const std::vector<int>& found = tree.query(query);
      for (int i = 0; i < 300; ++i) {
        const bool listed = std::find(found.begin(), found.end(), i) != found.end();
        if (stored[i] && within_linf(position[i], query, 2.0)) {
          ASSERT_TRUE(listed) << "id " << i;
        }
        if (!stored[i]) {
          ASSERT_FALSE(listed) << "removed id " << i << " still listed";
        }
      }
    }
  }
}

TEST(IncrementalOVLPQuadTree, OverlapLargerThanTheCellIsABug) {
  EXPECT_THROW(IncrementalOVLPQuadTree(1.0, 2.0), std::logic_error);
  EXPECT_THROW(OVLPQuadTree(1.0, 2.0), std::logic_error);
}

}  // namespace
}  // namespace relslam::spatial
