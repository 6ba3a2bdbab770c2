#include "relslam/point/rlt_interval.hpp"

#include "seeded_random.hpp"

#include <gtest/gtest.h>

#include <set>

namespace relslam::point {
namespace {

int brute_count(const std::set<int>& s, int a, int b) {
  int n = 0;
  for (int i : s) n += i >= a && i <= b;
  return n;
}

TEST(RltInterval, CountsMatchBruteForceForRandomSets) {
  test::SeededRandom rng(301);
  for (int trial = 0; trial < 20; ++trial) {
    RltInterval interval;
    std::set<int> truth;
    for (int it = 0; it < 500; ++it)
      if (rng.uniform() < 0.6) {
        interval.add(it);
        truth.insert(it);
      }
    for (int q = 0; q < 200; ++q) {
      const int a = static_cast<int>(rng.below(520)) - 10, b = a + static_cast<int>(rng.below(80));
      ASSERT_EQ(interval.count(a, b), brute_count(truth, a, b)) << "[" << a << ", " << b << "]";
    }
    EXPECT_EQ(interval.total(), static_cast<int>(truth.size()));
    for (std::size_t r = 1; r < interval.runs().size(); ++r)
      EXPECT_GT(interval.runs()[r].start, interval.runs()[r - 1].end + 1) << "runs are separated";
  }
}

TEST(RltInterval, InsertInAnyOrderKeepsRunsCanonical) {
  test::SeededRandom rng(302);
  RltInterval interval;
  std::set<int> truth;
  for (int i = 0; i < 300; ++i) {
    const int it = static_cast<int>(rng.below(200));
    interval.insert(it);
    truth.insert(it);
  }
  EXPECT_EQ(interval.total(), static_cast<int>(truth.size()));
  for (int a = -5; a < 205; a += 7) EXPECT_EQ(interval.count(a, a + 13), brute_count(truth, a, a + 13));
  for (std::size_t r = 1; r < interval.runs().size(); ++r)
    EXPECT_GT(interval.runs()[r].start, interval.runs()[r - 1].end + 1);
}

TEST(RltInterval, AddRefusesGoingBack) {
  RltInterval interval;
  interval.add(5);
  EXPECT_THROW(interval.add(5), std::logic_error);
  EXPECT_THROW(interval.add(3), std::logic_error);
  interval.add(6);
  EXPECT_EQ(interval.runs().size(), 1u);
  EXPECT_TRUE(interval.contains(6));
  EXPECT_FALSE(interval.contains(7));
}

}  // namespace
}  // namespace relslam::point
