// Scores of a path without ground truth: ATE against a reference path after 2-D alignment, and
// the gap at a revisited place (metrics/reference_path.hpp).
#include "relslam/eval/metrics/reference_path.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace relslam::eval {
namespace {

using Path = std::vector<std::optional<PlanarPose>>;

Path circle(int n, double radius) {
  Path p;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * k / n;
    p.push_back(PlanarPose::from(radius * std::cos(a), radius * std::sin(a), a + std::numbers::pi / 2));
  }
  return p;
}

TEST(AteVsReference, RigidlyMovedCopyScoresZero) {
  const Path reference = circle(40, 5.0);
  Path moved;
  const PlanarPose shift = PlanarPose::from(3.0, -2.0, 0.7);
  for (const auto& p : reference) moved.push_back(shift * *p);
  const ReferencePathError e = ate_vs_reference(moved, reference);
  EXPECT_EQ(e.pairs, 40);
  EXPECT_NEAR(e.ate, 0.0, 1e-9);
  EXPECT_NEAR(std::abs(e.rotation_deg), 0.7 * 180 / std::numbers::pi, 1e-6);
}

TEST(AteVsReference, KnownOffsetAndMissingPoses) {
  const Path reference = circle(40, 5.0);
  Path estimate = reference;
  // Alternate ±0.1 across the path's direction: alignment cannot remove it, RMS 0.1.
  for (std::size_t k = 0; k < estimate.size(); ++k) {
    const double s = k % 2 == 0 ? 0.1 : -0.1;
    estimate[k]->translation *= (5.0 + s) / 5.0;
  }
  estimate[3].reset();
  const ReferencePathError e = ate_vs_reference(estimate, reference);
  EXPECT_EQ(e.pairs, 39);
  EXPECT_NEAR(e.ate, 0.1, 2e-3);
  EXPECT_NEAR(e.max, 0.1, 3e-3);
  EXPECT_EQ(ate_vs_reference({}, reference).pairs, 0);
}

TEST(LoopGap, AsThePathSaysAndAgainstAReference) {
  Path path = {PlanarPose::from(0, 0, 0), PlanarPose::from(5, 0, 1.0), PlanarPose::from(0.3, 0.4, 0.1)};
  const std::optional<LoopGap> raw = loop_gap(path, 0, 2);
  ASSERT_TRUE(raw);
  EXPECT_NEAR(raw->distance, 0.5, 1e-12);
  EXPECT_NEAR(raw->heading_deg, 0.1 * 180 / std::numbers::pi, 1e-9);
  // The reference says the place is the same up to the same offset: no gap left.
  const Path reference = {PlanarPose::from(10, 10, 0), std::nullopt, PlanarPose::from(10.3, 10.4, 0.1)};
  const std::optional<LoopGap> rel = loop_gap(path, 0, 2, &reference);
  ASSERT_TRUE(rel);
  EXPECT_NEAR(rel->distance, 0.0, 1e-12);
  EXPECT_NEAR(rel->heading_deg, 0.0, 1e-9);
  EXPECT_FALSE(loop_gap(path, 0, 1, &reference));  // the reference has no pose there
  EXPECT_FALSE(loop_gap(path, 0, 3));
  EXPECT_FALSE(loop_gap(path, -1, 2));
}

}  // namespace
}  // namespace relslam::eval
