// SegComp (Hoover et al. 1996) on hand-made segmentations: each of the five classes, and the
// extraction score's wall pieces (a wall seen in two parts is two regions to find).
#include "relslam/eval/metrics/extraction_score.hpp"
#include "relslam/eval/metrics/segcomp.hpp"

#include <gtest/gtest.h>

#include <numeric>

namespace relslam::eval {
namespace {

std::vector<int> range(int from, int to) {
  std::vector<int> out(static_cast<std::size_t>(to - from));
  std::iota(out.begin(), out.end(), from);
  return out;
}

TEST(SegComp, OneToOneIsCorrect) {
  const std::vector<int> truth = {0, 0, 0, 0, 0, 1, 1, 1, 1, 1};
  const SegCompCounts c = segcomp(truth, 2, {range(0, 5), range(5, 10)}, 0.8);
  EXPECT_EQ(c.correct, 2);
  EXPECT_EQ(c.over_segmented + c.under_segmented + c.missed + c.noise, 0);
  EXPECT_EQ(c.correct_pairs, (std::vector<std::pair<int, int>>{{0, 0}, {1, 1}}));
}

TEST(SegComp, SplitIsOverSegmentedMergeIsUnderSegmented) {
  // Region 0 (10 points) split in two halves; regions 1 and 2 (5 each) found as one.
  std::vector<int> truth(20, 0);
  for (int i = 10; i < 15; ++i) truth[static_cast<std::size_t>(i)] = 1;
  for (int i = 15; i < 20; ++i) truth[static_cast<std::size_t>(i)] = 2;
  const SegCompCounts c = segcomp(truth, 3, {range(0, 5), range(5, 10), range(10, 20)}, 0.8);
  EXPECT_EQ(c.correct, 0);
  EXPECT_EQ(c.over_segmented, 1);
  EXPECT_EQ(c.under_segmented, 1);
  EXPECT_EQ(c.missed, 0);
  EXPECT_EQ(c.noise, 0);
}

TEST(SegComp, BelowTheToleranceIsMissedAndNoise) {
  // The machine region holds 7 of region 0's 10 points (< 0.8) and 3 points of no region.
  std::vector<int> truth(13, -1);
  for (int i = 0; i < 10; ++i) truth[static_cast<std::size_t>(i)] = 0;
  const SegCompCounts c = segcomp(truth, 1, {range(3, 13)}, 0.8);
  EXPECT_EQ(c.correct, 0);
  EXPECT_EQ(c.missed, 1);
  EXPECT_EQ(c.noise, 1);
  EXPECT_EQ(segcomp(truth, 1, {range(1, 10)}, 0.8).correct, 1);  // 9 of 10, all its own
}

// A wall along z = 2 (robot frame = world), seen as two pieces with a gap of 1 between them.
struct TwoPieces {
  std::vector<Eigen::Vector3d> points;
  std::vector<int> wall_ids;
  std::vector<PlaneObject> walls = {PlaneObject{{-5, 2}, {5, 2}}};
  std::vector<std::vector<int>> support = {{}, {}};
  TwoPieces() {
    for (int i = 0; i < 60; ++i) {
      const double x = i < 30 ? -4.0 + 0.1 * i : 0.0 + 0.1 * (i - 30);  // [-4, -1.1] and [0, 2.9]
      points.emplace_back(x, 0.5 + 0.1 * (i % 3), 2.0);
      wall_ids.push_back(0);
      support[i < 30 ? 0 : 1].push_back(i);
    }
  }
};

TEST(ExtractionScore, AWallSeenInTwoPiecesIsTwoRegions) {
  const TwoPieces s;
  const std::vector<PlaneObject> planes = {PlaneObject{{-4, 2}, {-1.1, 2}}, PlaneObject{{0, 2}, {2.9, 2}}};
  const ExtractionFrameScore score =
      score_extraction(s.points, s.wall_ids, s.walls, PlanarPose::identity(), planes, s.support, {});
  EXPECT_EQ(score.true_visible, 2);
  EXPECT_EQ(score.counts.correct, 2);
  EXPECT_DOUBLE_EQ(score.recall, 1.0);
  EXPECT_DOUBLE_EQ(score.precision, 1.0);
  EXPECT_NEAR(score.mean_normal_error_deg, 0.0, 1e-9);
  EXPECT_NEAR(score.mean_offset_error, 0.0, 1e-9);
  EXPECT_NEAR(score.mean_end_error, 0.0, 1e-9);

  // One plane over both pieces is an under-segmentation: nothing correct.
  std::vector<int> all(60);
  std::iota(all.begin(), all.end(), 0);
  const ExtractionFrameScore merged = score_extraction(s.points, s.wall_ids, s.walls, PlanarPose::identity(),
                                                       {PlaneObject{{-4, 2}, {2.9, 2}}}, {all}, {});
  EXPECT_EQ(merged.counts.under_segmented, 1);
  EXPECT_DOUBLE_EQ(merged.recall, 0.0);
  EXPECT_DOUBLE_EQ(merged.precision, 0.0);
}

TEST(ExtractionScore, TurnedPlaneHasItsAngleAsNormalError) {
  const TwoPieces s;
  // The first piece's plane turned by atan(0.1) about its start.
  const std::vector<PlaneObject> planes = {PlaneObject{{-4, 2}, {-1, 2.3}}, PlaneObject{{0, 2}, {2.9, 2}}};
  const ExtractionFrameScore score =
      score_extraction(s.points, s.wall_ids, s.walls, PlanarPose::identity(), planes, s.support, {});
  EXPECT_EQ(score.counts.correct, 2);
  EXPECT_NEAR(score.mean_normal_error_deg, 0.5 * std::atan(0.1) * 180.0 / M_PI, 1e-9);
}

}  // namespace
}  // namespace relslam::eval
