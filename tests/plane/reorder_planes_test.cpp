#include "relslam/plane/reorder_planes.hpp"

#include "clipped_wall_fixture.hpp"
#include "relslam/plane/key_point_compare.hpp"
#include "relslam/plane/rlt_xpoint.hpp"
#include "seeded_random.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <vector>

namespace relslam::plane {
namespace {

using Weights = std::vector<std::vector<int>>;

long long path_weight(const Weights& w, const std::vector<int>& order) {
  long long sum = 0;
  for (std::size_t k = 1; k < order.size(); ++k) {
    if (w[order[k - 1]][order[k]] < 0) return -1;
    sum += w[order[k - 1]][order[k]];
  }
  return sum;
}

// Every order, the best usable one's weight (−1: none).
long long brute_force(const Weights& w) {
  std::vector<int> order(w.size());
  std::iota(order.begin(), order.end(), 0);
  long long best = -1;
  do best = std::max(best, path_weight(w, order));
  while (std::ranges::next_permutation(order).found);
  return best;
}

Weights random_weights(int n, relslam::test::SeededRandom& random, double excluded_share) {
  Weights w(n, std::vector<int>(n, -1));
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      w[i][j] = w[j][i] = random.uniform() < excluded_share ? -1 : static_cast<int>(random.uniform() * 100);
  return w;
}

bool is_permutation_of_all(std::vector<int> order, int n) {
  std::ranges::sort(order);
  std::vector<int> all(n);
  std::iota(all.begin(), all.end(), 0);
  return order == all;
}

// thesis 4.3.7.1: the exact search finds the heaviest path over usable pairs, whatever the graph.
TEST(BestComparisonPath, ExactSearchMatchesEveryOrderTried) {
  relslam::test::SeededRandom random(30);
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 2 + trial % 6;
    const Weights w = random_weights(n, random, trial % 3 == 0 ? 0.5 : 0.2);
    const long long best = brute_force(w);
    const auto path = best_comparison_path(w, 12);
    if (best < 0) {
      EXPECT_FALSE(path) << "trial " << trial;
      continue;
    }
    ASSERT_TRUE(path) << "trial " << trial;
    EXPECT_TRUE(is_permutation_of_all(*path, n));
    EXPECT_EQ(path_weight(w, *path), best) << "trial " << trial;
  }
}

// The collinear pair of Fig 97 (excluded) is never an edge; the path goes round it.
TEST(BestComparisonPath, GoesRoundAnExcludedPair) {
  const Weights w = {{-1, -1, 30}, {-1, -1, 20}, {30, 20, -1}};
  const auto path = best_comparison_path(w, 12);
  ASSERT_TRUE(path);
  EXPECT_EQ(*path, (std::vector<int>{0, 2, 1}));
  EXPECT_FALSE(best_comparison_path({{-1, -1}, {-1, -1}}, 12));  // no usable pair: keep the order
  EXPECT_FALSE(best_comparison_path({{-1}}, 12));
}

// Beyond exact_max the greedy search still returns a path over usable pairs only, and on a
// graph whose heaviest edges form a path it finds that path.
TEST(BestComparisonPath, GreedyBeyondTheExactLimitUsesUsablePairsOnly) {
  relslam::test::SeededRandom random(31);
  for (int trial = 0; trial < 20; ++trial) {
    const Weights w = random_weights(16, random, 0.3);
    const auto path = best_comparison_path(w, 12);
    if (path) {
      EXPECT_TRUE(is_permutation_of_all(*path, 16));
      EXPECT_GE(path_weight(w, *path), 0);
    }
  }
  Weights line(14, std::vector<int>(14, 1));
  for (int i = 0; i + 1 < 14; ++i) line[i][i + 1] = line[i + 1][i] = 100;
  const auto path = best_comparison_path(line, 12);
  ASSERT_TRUE(path);
  EXPECT_EQ(path_weight(line, *path), 13 * 100);
}

using test::ClippedWall;

// Fig 97 in miniature: the robot drives along a wall line at z = −6 with a window
// [w − 10, w], w = 1 + 0.15·t, for 40 iterations: the wall it leaves (x −9..−1) shrinks from its
// left, the next one (x 0..8) grows to its right, and both cut ends move with the window — both
// diagonals of Rule 13 are constant (Rule 15's tie), the offset wrong by one diagonal. A cross wall at x = 4,
// seen whole throughout, gives each of them its key point.
const ClippedWall kLeaving{{-9, -6}, {-1, -6}, [](int t) { return std::min(8.0, 0.15 * t); }, test::constant(8)};
const ClippedWall kEntering{{0, -6}, {8, -6}, test::constant(0), [](int t) { return std::min(8.0, 1 + 0.15 * t); }};
const ClippedWall kCross{{4, -5}, {4, 3}, test::constant(0), test::constant(8)};

std::vector<RltPlane> collinear_planes() {
  std::vector<RltPlane> planes;
  relslam::test::SeededRandom random(1);
  for (const ClippedWall* wall : {&kLeaving, &kEntering, &kCross}) {
    const std::vector<PlaneObject> seen = test::observe_clipped(*wall, 0, 40, {}, random);
    planes.emplace_back(static_cast<PlaneId>(planes.size()), seen.front(), 1200);
    for (std::size_t t = 1; t < seen.size(); ++t) planes.back().add(seen[t]);
  }
  return planes;
}

RelativePlaneOptions noise_free() {
  RelativePlaneOptions options;
  options.key_points = true;
  options.rules.reorder_planes = true;
  options.key_point_ties.collinear_distance = false;  // Rule 30's own way past the Fig 97 tie
  options.growth_phase.window = 1;
  options.same_length = 1e-9;
  return options;
}

// Rule 30: at the group's age first_age (not before), the chain that joined the two collinear
// planes directly becomes one through the cross wall; every plane is then placed exactly where
// its wall is (each reference at its canonical size from its key point), and the next search
// waits `period` iterations.
TEST(RltXPointReorder, Rule30ChainsTheCollinearPairThroughAPartnerWithKeyPoints) {
  const RelativePlaneOptions options = noise_free();
  std::vector<RltPlane> planes = collinear_planes();
  const auto stored = [&](PlaneId p) {
    std::vector<PlaneObject> out;
    for (int i = 0; i < planes[p].size(); ++i) out.push_back(planes[p][i]);
    return out;
  };
  ASSERT_TRUE(compare_with_key_points(stored(0), stored(1), options).ambiguous);  // Rule 15's tie
  RltXPoint group(0, 0, {0, 1, 2});
  for (PlaneId p = 0; p < 3; ++p) planes[p].join(0, 0);
  EXPECT_FALSE(group.reorder_if_due(planes, options, options.reorder.first_age - 1));
  EXPECT_EQ(group.planes(), (std::vector<PlaneId>{0, 1, 2}));
  ASSERT_TRUE(group.reorder_if_due(planes, options, options.reorder.first_age));
  const std::vector<PlaneId> chain = group.planes();
  for (std::size_t k = 1; k < chain.size(); ++k)
    EXPECT_FALSE((chain[k - 1] == 0 && chain[k] == 1) || (chain[k - 1] == 1 && chain[k] == 0))
        << "the collinear pair is still an edge";
  EXPECT_FALSE(group.reorder_if_due(planes, options, options.reorder.first_age + options.reorder.period - 1));

  group.compute(planes, options);
  const ClippedWall* walls[] = {&kLeaving, &kEntering, &kCross};
  for (const RltXPointRef* ref : {planes[0].ref(0), planes[1].ref(0), planes[2].ref(0)}) ASSERT_TRUE(ref->valid);
  // The relative map: each plane's reference in the frame of plane 2's (the cross wall, whole).
  const auto truth = [&](PlaneId p) {
    const RltXPointRef& r = *planes[p].ref(0);
    return walls[p]->anchored(r.max_length, r.key_point == KeyPoint::None ? KeyPoint::Left : r.key_point).pose();
  };
  for (PlaneId p : {0, 1}) {
    const PlanarPose expected = truth(2).inverse() * truth(p);
    const PlanarPose found = planes[2].ref(0)->pose.inverse() * planes[p].ref(0)->pose;
    EXPECT_LT((found.translation - expected.translation).norm(), 1e-9) << "plane " << p;
    EXPECT_LT(std::abs(wrap_angle(found.heading - expected.heading)), 1e-9) << "plane " << p;
  }
  EXPECT_EQ(planes[0].ref(0)->key_point, KeyPoint::Right);  // the leaving wall's real end
  EXPECT_EQ(planes[1].ref(0)->key_point, KeyPoint::Left);   // the entering wall's real end
}

}  // namespace
}  // namespace relslam::plane
