#include "relslam/eval/metrics/seed_statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace relslam::eval {
namespace {

TEST(SeedStatistics, MeanSampleStdAndStudentInterval) {
  const SeedStatistics s = seed_statistics({1, 2, 3, 4});
  EXPECT_EQ(s.n, 4);
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.std, std::sqrt(5.0 / 3.0));
  EXPECT_DOUBLE_EQ(s.ci95, 3.182 * std::sqrt(5.0 / 3.0) / 2.0);  // t(0.975, 3 dof) = 3.182
}

TEST(SeedStatistics, TwoSeedsUseTwelvePointSevenAndManySeedsTheNormalQuantile) {
  const SeedStatistics two = seed_statistics({1, 3});
  EXPECT_DOUBLE_EQ(two.ci95, 12.706 * std::sqrt(2.0) / std::sqrt(2.0));
  std::vector<double> many(40);
  for (std::size_t i = 0; i < many.size(); ++i) many[i] = static_cast<double>(i % 2);
  const SeedStatistics s = seed_statistics(many);
  EXPECT_DOUBLE_EQ(s.ci95, 1.960 * s.std / std::sqrt(40.0));
}

TEST(SeedStatistics, NonFiniteValuesAreSkippedAndNothingGivesNaN) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const SeedStatistics s = seed_statistics({2, nan, 4, std::numeric_limits<double>::infinity()});
  EXPECT_EQ(s.n, 2);
  EXPECT_DOUBLE_EQ(s.mean, 3.0);
  const SeedStatistics one = seed_statistics({7});
  EXPECT_EQ(one.std, 0.0);
  EXPECT_EQ(one.ci95, 0.0);
  EXPECT_TRUE(std::isnan(seed_statistics({nan}).mean));
  EXPECT_TRUE(std::isnan(seed_statistics({}).ci95));
}

}  // namespace
}  // namespace relslam::eval
