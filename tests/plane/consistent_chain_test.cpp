// The comparison chain through consistent ends (consistent_chain.hpp): every inner plane is
// entered and left on one end, so Rule 28's size correction never joins two pieces of a wall
// seen only in parts.
#include "relslam/plane/consistent_chain.hpp"

#include "seeded_random.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <vector>

namespace relslam::plane {
namespace {

using Weights = std::vector<std::vector<int>>;
using Ends = std::vector<std::vector<KeyPoint>>;

long long consistent_weight(const Weights& w, const Ends& e, const std::vector<int>& order) {
  if (!consistent_chain(order, w, e)) return -1;
  long long sum = 0;
  for (std::size_t k = 1; k < order.size(); ++k) sum += w[order[k - 1]][order[k]];
  return sum;
}

long long brute_force(const Weights& w, const Ends& e) {
  std::vector<int> order(w.size());
  std::iota(order.begin(), order.end(), 0);
  long long best = -1;
  do best = std::max(best, consistent_weight(w, e, order));
  while (std::ranges::next_permutation(order).found);
  return best;
}

TEST(BestConsistentPath, ExactSearchMatchesEveryOrderTried) {
  relslam::test::SeededRandom random(37);
  const KeyPoint kinds[] = {KeyPoint::None, KeyPoint::Left, KeyPoint::Right};
  for (int trial = 0; trial < 80; ++trial) {
    const int n = 2 + trial % 6;
    Weights w(n, std::vector<int>(n, -1));
    Ends e(n, std::vector<KeyPoint>(n, KeyPoint::None));
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        if (i < j) w[i][j] = w[j][i] = random.uniform() < 0.2 ? -1 : static_cast<int>(random.uniform() * 100);
        if (i != j) e[i][j] = kinds[static_cast<int>(random.uniform() * 2.999)];
      }
    const long long best = brute_force(w, e);
    const auto path = best_consistent_path(w, e, 12);
    if (best < 0) {
      EXPECT_FALSE(path) << "trial " << trial;
      continue;
    }
    ASSERT_TRUE(path) << "trial " << trial;
    std::vector<int> sorted = *path;
    std::ranges::sort(sorted);
    std::vector<int> all(n);
    std::iota(all.begin(), all.end(), 0);
    EXPECT_EQ(sorted, all);
    EXPECT_EQ(consistent_weight(w, e, *path), best) << "trial " << trial;
  }
}

// The corridor of the generated map (seed 1, small frustum): the two sides' pieces 0 and 1, each
// seen at its left end with the one and at its right end with the other, and the end wall 2 seen
// whole. The order they joined in (0, 1, 2) passes piece 1 on both ends; through the whole wall
// (0, 2, 1) every piece keeps one end.
TEST(BestConsistentPath, GoesThroughTheWallSeenWhole) {
  const Weights w = {{-1, 28, 60}, {28, -1, 74}, {60, 74, -1}};
  const Ends e = {{KeyPoint::None, KeyPoint::Right, KeyPoint::Left},
                  {KeyPoint::Left, KeyPoint::None, KeyPoint::Right},
                  {KeyPoint::None, KeyPoint::None, KeyPoint::None}};
  EXPECT_FALSE(consistent_chain({0, 1, 2}, w, e));
  const auto path = best_consistent_path(w, e, 12);
  ASSERT_TRUE(path);
  EXPECT_EQ(*path, (std::vector<int>{0, 2, 1}));
  EXPECT_TRUE(consistent_chain(*path, w, e));
  // Without the whole wall's edges no order passes the pieces on one end.
  const Weights cut = {{-1, 28, 60}, {28, -1, -1}, {60, -1, -1}};
  const Ends two_ends = {{KeyPoint::None, KeyPoint::Right, KeyPoint::Left},
                         {KeyPoint::Left, KeyPoint::None, KeyPoint::None},
                         {KeyPoint::None, KeyPoint::None, KeyPoint::None}};
  EXPECT_FALSE(best_consistent_path(cut, two_ends, 12));
  EXPECT_FALSE(best_consistent_path({{-1}}, {{KeyPoint::None}}, 12));
}

}  // namespace
}  // namespace relslam::plane
