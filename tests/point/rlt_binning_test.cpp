#include "relslam/point/rlt_binning.hpp"

#include "seeded_random.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace relslam::point {
namespace {

// Synthetic untransformed tracks (thesis 6.5.3): static points jitter by sigma 0.1 per axis around
// fixed positions; uncorrelated points jitter by 1.0 more. 60 iterations each. The
// uncorrelated ones are a random subset; `noisy` says which.
std::vector<ObservationRing> tracks(int n, int uncorrelated, std::uint64_t seed, std::vector<bool>* noisy = nullptr) {
  test::SeededRandom rng(seed);
  std::vector<bool> is_noisy(static_cast<std::size_t>(n), false);
  std::fill(is_noisy.begin(), is_noisy.begin() + uncorrelated, true);
  for (int i = n - 1; i > 0; --i)
    std::vector<bool>::swap(is_noisy[i], is_noisy[rng.below(static_cast<std::uint64_t>(i) + 1)]);
  if (noisy) *noisy = is_noisy;
  std::vector<ObservationRing> rings(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d base(rng.uniform(-50, 50), rng.uniform(-5, 5), rng.uniform(0, 100));
    const double sigma = is_noisy[i] ? std::hypot(0.1, 1.0) : 0.1;
    for (int t = 0; t < 60; ++t)
      rings[i].push({base + sigma * Eigen::Vector3d(rng.gaussian(), rng.gaussian(), rng.gaussian()), t});
  }
  return rings;
}

BinningResult bin(const std::vector<ObservationRing>& rings, const BinningOptions& o = {}) {
  return rlt_binning(
      static_cast<int>(rings.size()),
      [&](int i, int j) { return pair_distance_std(rings[i], rings[j], 0, 59, o.min_pair_samples); }, o);
}

TEST(RltBinning, AllStaticPointsFormOneBinInNMinusOneComparisons) {
  for (int n : {2, 3, 7, 20, 64, 101}) {
    const BinningResult r = bin(tracks(n, 0, 11));
    EXPECT_EQ(r.highest_bin, n) << "n " << n;
    EXPECT_EQ(r.comparisons, n - 1) << "n " << n;
  }
}

TEST(RltBinning, EveryBinPairingSpendsOneExtraComparisonOnAllStaticPoints) {
  BinningOptions o;
  o.pairing = BinPairing::EveryBin;
  const BinningResult r = bin(tracks(50, 0, 12), o);
  EXPECT_EQ(r.highest_bin, 50);
  EXPECT_EQ(r.comparisons, 50) << "the last bin of the first round compares back with the first";
}

TEST(RltBinning, FlagsExactlyTheUncorrelatedPointsUpToFortyPercent) {
  for (BinPairing pairing : {BinPairing::Disjoint, BinPairing::EveryBin})
    for (bool heuristic : {true, false})
      for (int n : {20, 50, 100, 200})
        for (int percent : {5, 10, 20, 30, 40})
          for (std::uint64_t seed : {1, 2, 3}) {
            const int uncorrelated = n * percent / 100;
            BinningOptions o;
            o.pairing = pairing;
            o.priority_heuristic = heuristic;
            std::vector<bool> noisy;
            const BinningResult r = bin(tracks(n, uncorrelated, seed, &noisy), o);
            for (int i = 0; i < n; ++i)
              ASSERT_EQ(r.is_static[i], !noisy[i])
                  << "n " << n << " " << percent << "% seed " << seed << " heuristic " << heuristic << " point " << i;
          }
}

TEST(RltBinning, HeuristicKeepsComparisonsBelowNLogNUpToFortyPercent) {
  // Thesis Figs 115-116: with the priority heuristic the comparisons stay at or below n ln n
  // until close to the 50 % majority threshold.
  for (BinPairing pairing : {BinPairing::Disjoint, BinPairing::EveryBin})
    for (int percent : {10, 20, 30, 40}) {
      BinningOptions o;
      o.pairing = pairing;
      double mean = 0;
      for (std::uint64_t seed = 1; seed <= 5; ++seed) mean += bin(tracks(200, 2 * percent, seed), o).comparisons / 5.0;
      EXPECT_LT(mean, 200 * std::log(200.0)) << percent << "%";
      EXPECT_GT(mean, 199);
    }
}

TEST(RltBinning, ThresholdSitsAboveTheFirstGap) {
  BinningOptions o;
  // Static cluster 0.10-0.16, then a jump to 1.2: threshold = 0.16 + half the minimum gap.
  EXPECT_DOUBLE_EQ(binning_threshold({0.14, 0.10, 1.2, 0.16, 1.5, 0.12}, o), 0.16 + 0.5 * std::max(0.05, 0.5 * 0.16));
  o.threshold_margin = false;
  EXPECT_DOUBLE_EQ(binning_threshold({0.14, 0.10, 1.2, 0.16, 1.5, 0.12}, o), 0.16);
}

TEST(RltBinning, ThresholdWithoutAGapIsAboveEverything) {
  const BinningOptions o;
  // Evenly spread deviations: no step exceeds both the absolute and the relative gap.
  const double t = binning_threshold({0.10, 0.13, 0.16, 0.19, 0.22}, o);
  EXPECT_GT(t, 0.22);
  EXPECT_EQ(binning_threshold({}, o), 0.0);
  EXPECT_EQ(binning_threshold({std::numeric_limits<double>::infinity()}, o), 0.0);
}

TEST(RltBinning, PairDeviationUsesOnlyCommonIterationsInTheWindow) {
  ObservationRing a, b;
  for (int t = 0; t < 20; ++t) a.push({Eigen::Vector3d(0, 0, 0), t});
  for (int t = 10; t < 30; t += 2) b.push({Eigen::Vector3d(t % 4 == 0 ? 1.0 : 3.0, 0, 0), t});
  // Common iterations 10..18 step 2: distances 3,1,3,1,3 -> std of {3,1,3,1,3}.
  const double mean = 11.0 / 5.0;
  const double expected = std::sqrt((3 * std::pow(3 - mean, 2) + 2 * std::pow(1 - mean, 2)) / 5.0);
  EXPECT_NEAR(pair_distance_std(a, b, 0, 19, 5), expected, 1e-12);
  EXPECT_TRUE(std::isinf(pair_distance_std(a, b, 0, 19, 6))) << "only 5 common iterations";
  EXPECT_TRUE(std::isinf(pair_distance_std(a, b, 25, 40, 1))) << "a ends before the window";
}

}  // namespace
}  // namespace relslam::point
