#include "relslam/plane/growth_phase.hpp"

#include "seeded_random.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace relslam::plane {
namespace {

const GrowthPhaseBounds kBounds;  // defaults: w_ma 5, h 0.03, n_min_cmp 3

// Grow by `rate` per iteration for `grow` iterations, hold for `plateau`, shrink for `shrink`,
// plus seeded Gaussian noise of `sigma` per sample.
std::vector<double> grow_plateau_shrink(int grow, int plateau, int shrink, double rate, double sigma,
                                        std::uint64_t seed) {
  test::SeededRandom random(seed);
  std::vector<double> lengths;
  double l = 1;
  for (int k = 0; k < grow + plateau + shrink; ++k) {
    if (k > 0 && k < grow) l += rate;
    if (k >= grow + plateau) l -= rate;
    lengths.push_back(l + sigma * random.gaussian());
  }
  return lengths;
}

std::vector<SizeSample> samples_of(const std::vector<double>& l1, const std::vector<double>& l2, int first = 100) {
  std::vector<SizeSample> samples;
  for (std::size_t k = 0; k < l1.size(); ++k) samples.push_back({first + static_cast<int>(k), l1[k], l2[k]});
  return samples;
}

TEST(GrowthPhaseSplits, ConstantOrSlightlyNoisyLengthsNeverSplit) {
  EXPECT_TRUE(growth_phase_splits(std::vector<double>(50, 3.0), 5, 0.03).empty());
  for (std::uint64_t seed = 1; seed <= 5; ++seed)  // σ 0.01 = h/3: the average moves < h
    EXPECT_TRUE(growth_phase_splits(grow_plateau_shrink(1, 60, 0, 0, 0.01, seed), 5, 0.03).empty()) << seed;
}

TEST(GrowthPhaseSplits, GrowingOnlyNeverSplits) {
  EXPECT_TRUE(growth_phase_splits(grow_plateau_shrink(40, 0, 0, 0.1, 0, 1), 5, 0.03).empty());
  EXPECT_TRUE(growth_phase_splits(grow_plateau_shrink(1, 0, 40, 0.1, 0, 1), 5, 0.03).empty());
}

// A sharp peak at k = 29: the trailing average over 5 peaks at 29 + 2 — the lag of (w − 1)/2 the
// thesis's Fig 105 suffers from.
TEST(GrowthPhaseSplits, SharpPeakSplitsHalfAWindowLate) {
  const std::vector<double> peak = grow_plateau_shrink(30, 0, 30, 0.1, 0, 1);
  EXPECT_EQ(growth_phase_splits(peak, 5, 0.03), std::vector<int>{31});
  EXPECT_EQ(growth_phase_splits(peak, 1, 0.03), std::vector<int>{29});  // no average: no lag
}

// grow → plateau → shrink with noise splits once, within ± w_ma of the plateau.
TEST(GrowthPhaseSplits, GrowPlateauShrinkWithNoiseSplitsOnceInsideThePlateau) {
  const int grow = 30, plateau = 15, shrink = 30;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const std::vector<int> splits =
        growth_phase_splits(grow_plateau_shrink(grow, plateau, shrink, 0.1, 0.01, seed), kBounds.window, 0.03);
    ASSERT_EQ(splits.size(), 1u) << "seed " << seed;
    EXPECT_GE(splits[0], grow - 1 - kBounds.window) << "seed " << seed;
    EXPECT_LE(splits[0], grow + plateau - 1 + kBounds.window) << "seed " << seed;
  }
}

// Shrink → grow → shrink (a plane leaving, then seen again from a turn): two splits, each within
// ± w_ma of the true turning point.
TEST(GrowthPhaseSplits, ValleyThenPeakSplitsTwiceNearEachTurn) {
  test::SeededRandom random(7);
  std::vector<double> lengths;
  for (int k = 0; k < 75; ++k) {
    const double l = k < 25 ? 5 - 0.1 * k : k < 50 ? 2.5 + 0.1 * (k - 25) : 5 - 0.1 * (k - 50);
    lengths.push_back(l + 0.01 * random.gaussian());
  }
  const std::vector<int> splits = growth_phase_splits(lengths, kBounds.window, kBounds.hysteresis);
  ASSERT_EQ(splits.size(), 2u);
  EXPECT_NEAR(splits[0], 25, kBounds.window);
  EXPECT_NEAR(splits[1], 50, kBounds.window);
}

TEST(SplitByGrowthPhase, EitherPlanesSwitchSplitsThePair) {
  // Plane 1 peaks at 29 (split at 31), plane 2 only shrinks, then valleys at 59 (split at 61).
  std::vector<double> l1 = grow_plateau_shrink(30, 0, 50, 0.05, 0, 1);
  std::vector<double> l2;
  for (int k = 0; k < 80; ++k) l2.push_back(k < 60 ? 8 - 0.1 * k : 2.1 + 0.1 * (k - 59));
  const std::vector<SizeInterval> intervals = split_by_growth_phase(samples_of(l1, l2), kBounds);
  ASSERT_EQ(intervals.size(), 3u);
  EXPECT_EQ(intervals[0].interval.start, 100);
  EXPECT_EQ(intervals[0].interval.end, 131);
  EXPECT_EQ(intervals[1].interval.start, 132);
  EXPECT_EQ(intervals[1].interval.end, 161);
  EXPECT_EQ(intervals[2].interval.start, 162);
  EXPECT_EQ(intervals[2].interval.end, 179);
  EXPECT_EQ(intervals[1].first, 32);
  EXPECT_EQ(intervals[1].samples, 30);
  // The maximum sizes are the raw lengths' maxima inside each piece.
  EXPECT_DOUBLE_EQ(intervals[0].length1, l1[29]);
  EXPECT_DOUBLE_EQ(intervals[0].length2, 8);
  EXPECT_DOUBLE_EQ(intervals[1].length1, l1[32]);
  EXPECT_DOUBLE_EQ(intervals[1].length2, l2[32]);
  EXPECT_DOUBLE_EQ(intervals[2].length2, l2[79]);
}

TEST(SplitByGrowthPhase, MissingIterationsBreakTheRunAndShortPiecesAreDropped) {
  std::vector<SizeSample> samples = samples_of(std::vector<double>(10, 2), std::vector<double>(10, 3));
  const std::vector<SizeSample> tail = samples_of(std::vector<double>(2, 4), std::vector<double>(2, 3), 111);
  samples.insert(samples.end(), tail.begin(), tail.end());  // 100..109, then 111..112
  const std::vector<SizeInterval> intervals = split_by_growth_phase(samples, kBounds);
  ASSERT_EQ(intervals.size(), 1u);  // 111..112 has 2 < n_min_cmp samples
  EXPECT_EQ(intervals[0].interval.start, 100);
  EXPECT_EQ(intervals[0].interval.end, 109);
  EXPECT_DOUBLE_EQ(intervals[0].length1, 2);  // the dropped piece's 4 does not count
}

// Rule 18 takes the piece with the most iterations; the walkthrough's choice the largest size.
TEST(GetMaxSize, ChoosesByIterationsOrBySizeOrByForcedIteration) {
  // Plane 1 grows for 40 iterations to 5, then shrinks for 20 (split at 41); plane 2 static.
  const std::vector<double> l1 = grow_plateau_shrink(40, 0, 20, 0.1, 0, 1);
  const std::vector<SizeSample> samples = samples_of(l1, std::vector<double>(60, 2));
  const auto most = get_max_size(samples, kBounds, IntervalChoice::MostIterations);
  ASSERT_TRUE(most);
  EXPECT_EQ(most->interval.start, 100);
  EXPECT_EQ(most->interval.end, 141);
  // The first piece also holds the peak, so the largest size agrees here.
  const auto largest = get_max_size(samples, kBounds, IntervalChoice::LargestSize);
  ASSERT_TRUE(largest);
  EXPECT_EQ(largest->interval.start, 100);
  EXPECT_DOUBLE_EQ(largest->length1, l1[39]);
  const auto forced = get_max_size(samples, kBounds, IntervalChoice::MostIterations, 150);
  ASSERT_TRUE(forced);
  EXPECT_EQ(forced->interval.start, 142);
  EXPECT_EQ(forced->interval.end, 159);
  EXPECT_FALSE(get_max_size(samples, kBounds, IntervalChoice::MostIterations, 99));
  EXPECT_FALSE(get_max_size({}, kBounds, IntervalChoice::MostIterations));
}

TEST(GetMaxSize, LargestSizeCanPreferTheShorterPiece) {
  // Plane 1 shrinks 9 → 7.5 over 16 iterations, then grows slowly to 8.38 over 44: the valley
  // splits at 119 (the average's minimum), so the short first piece holds the largest size.
  std::vector<double> l1;
  for (int k = 0; k < 16; ++k) l1.push_back(9 - 0.1 * k);
  for (int k = 16; k < 60; ++k) l1.push_back(7.5 + 0.02 * (k - 15));
  const std::vector<SizeSample> samples = samples_of(l1, std::vector<double>(60, 2));
  const auto most = get_max_size(samples, kBounds, IntervalChoice::MostIterations);
  const auto largest = get_max_size(samples, kBounds, IntervalChoice::LargestSize);
  ASSERT_TRUE(most && largest);
  EXPECT_GT(most->samples, largest->samples);
  EXPECT_DOUBLE_EQ(largest->length1, 9);
  EXPECT_EQ(largest->interval.start, 100);
}

}  // namespace
}  // namespace relslam::plane
