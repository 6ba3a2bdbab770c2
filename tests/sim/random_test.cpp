#include "relslam/sim/random.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace relslam::sim {
namespace {

TEST(RandomSequence, SameKeyGivesSameSequence) {
  RandomSequence a(42, Stream::Noise, 7, 9), b(42, Stream::Noise, 7, 9);
  for (int i = 0; i < 100; ++i) ASSERT_EQ(a.next_u64(), b.next_u64()) << "draw " << i;
}

TEST(RandomSequence, EveryKeyPartChangesTheSequence) {
  const std::uint64_t base = RandomSequence(42, Stream::Noise, 7, 9).next_u64();
  EXPECT_NE(base, RandomSequence(43, Stream::Noise, 7, 9).next_u64());
  EXPECT_NE(base, RandomSequence(42, Stream::Field, 7, 9).next_u64());
  EXPECT_NE(base, RandomSequence(42, Stream::Noise, 8, 9).next_u64());
  EXPECT_NE(base, RandomSequence(42, Stream::Noise, 7, 10).next_u64());
  EXPECT_NE(base, RandomSequence(42, Stream::Noise, 9, 7).next_u64()) << "swapped indices must differ";
}

TEST(RandomSequence, UniformStaysInUnitIntervalWithMeanHalf) {
  RandomSequence rng(1, Stream::Field);
  double sum = 0;
  constexpr int kN = 200000;
  for (int i = 0; i < kN; ++i) {
    const double u = rng.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
  }
  // Standard error of the mean is 1/sqrt(12 N) = 6.5e-4; 5 standard errors.
  EXPECT_NEAR(sum / kN, 0.5, 5 * 6.5e-4);
}

TEST(RandomSequence, BelowCoversTheRangeAndNothingElse) {
  RandomSequence rng(3, Stream::Shuffle);
  std::set<std::uint64_t> seen;
  for (int i = 0; i < 1000; ++i) {
    const std::uint64_t v = rng.below(7);
    ASSERT_LT(v, 7u);
    seen.insert(v);
  }
  EXPECT_EQ(seen.size(), 7u);
}

TEST(RandomSequence, GaussianHasZeroMeanUnitVarianceAndNormalTails) {
  RandomSequence rng(5, Stream::Noise);
  constexpr int kN = 400000;
  double sum = 0, sum2 = 0;
  int beyond2 = 0;
  for (int i = 0; i < kN; ++i) {
    const double g = rng.gaussian();
    sum += g;
    sum2 += g * g;
    beyond2 += std::abs(g) > 2.0;
  }
  const double mean = sum / kN, variance = sum2 / kN - mean * mean;
  EXPECT_NEAR(mean, 0.0, 5.0 / std::sqrt(kN));
  EXPECT_NEAR(variance, 1.0, 5.0 * std::sqrt(2.0 / kN));
  // P(|g| > 2) = 0.0455 for a normal distribution; binomial standard error ~3.3e-4.
  EXPECT_NEAR(static_cast<double>(beyond2) / kN, 0.0455, 5 * 3.3e-4);
}

}  // namespace
}  // namespace relslam::sim
