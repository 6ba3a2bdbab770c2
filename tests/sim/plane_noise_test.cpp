#include "relslam/sim/plane_noise.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace relslam::sim {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
// Lengths and midpoints recomputed from moved ends of size ~10: a few ulps.
constexpr double kRoundoff = 1e-12;

const Eigen::Vector2d kA(3, -2), kB(3, 2);

TEST(PlaneNoise, DefaultsAreTheSpecsWithNoiseValues) {
  const PlaneNoiseOptions o;
  EXPECT_EQ(o.model, PlaneNoiseModel::Gaussian);
  EXPECT_EQ(o.position, 0.01);
  EXPECT_DOUBLE_EQ(o.rotation_rad, 0.3 * kDegree);
  EXPECT_EQ(o.end_sigma, 0.0);
  EXPECT_TRUE(check(o).empty());
  EXPECT_TRUE(check(PlaneNoiseOptions::small_noise()).empty());
  EXPECT_EQ(PlaneNoiseOptions::small_noise().position, 0.005);
}

TEST(PlaneNoise, ModelNamesRoundTrip) {
  for (PlaneNoiseModel m : {PlaneNoiseModel::None, PlaneNoiseModel::Gaussian, PlaneNoiseModel::Uniform,
                            PlaneNoiseModel::ThreeValuedRotation})
    EXPECT_EQ(parse_plane_noise_model(to_string(m)), m);
  EXPECT_FALSE(parse_plane_noise_model("gauss"));
}

TEST(PlaneNoise, ZeroNoiseLeavesTheWallBitForBit) {
  PlaneNoiseOptions zero;
  zero.position = 0;
  zero.rotation_rad = 0;
  for (const PlaneNoiseOptions& o : {zero, PlaneNoiseOptions::none()})
    for (int k = 0; k < 20; ++k) {
      const auto [a, b] = draw_wall_noise(o, 1, 4, k).apply(kA, kB);
      EXPECT_EQ(a, kA);
      EXPECT_EQ(b, kB);
    }
}

TEST(PlaneNoise, ThreeValuedRotationCyclesMinusZeroPlus) {
  PlaneNoiseOptions o;
  o.model = PlaneNoiseModel::ThreeValuedRotation;
  const double e = o.rotation_rad;
  for (int wall = 0; wall < 3; ++wall) {
    const double expected[] = {-e, 0, e, -e, 0, e};
    for (int k = 0; k < 6; ++k) EXPECT_EQ(draw_wall_noise(o, 9, wall, k).rotation_rad, expected[k]) << "k " << k;
  }
  // Position noise is unchanged: the same draws as the Gaussian model.
  PlaneNoiseOptions gaussian = o;
  gaussian.model = PlaneNoiseModel::Gaussian;
  EXPECT_EQ(draw_wall_noise(o, 9, 1, 5).translation, draw_wall_noise(gaussian, 9, 1, 5).translation);
}

TEST(PlaneNoise, GaussianDrawsHaveTheRequestedSpread) {
  const PlaneNoiseOptions o;
  constexpr int kDraws = 20000;
  double sum_r = 0, sum_r2 = 0, sum_x2 = 0;
  for (int k = 0; k < kDraws; ++k) {
    const WallNoise n = draw_wall_noise(o, 3, 7, k);
    sum_r += n.rotation_rad;
    sum_r2 += n.rotation_rad * n.rotation_rad;
    sum_x2 += n.translation.squaredNorm();
  }
  // 20,000 draws: the sample sigma is within ~1 % of the truth; 3 % leaves room.
  EXPECT_NEAR(std::sqrt(sum_r2 / kDraws), o.rotation_rad, 0.03 * o.rotation_rad);
  EXPECT_NEAR(sum_r / kDraws, 0, 0.03 * o.rotation_rad);
  EXPECT_NEAR(std::sqrt(sum_x2 / (2 * kDraws)), o.position, 0.03 * o.position);
}

TEST(PlaneNoise, UniformDrawsStayWithinTheHalfWidth) {
  PlaneNoiseOptions o;
  o.model = PlaneNoiseModel::Uniform;
  double largest = 0;
  for (int k = 0; k < 5000; ++k) {
    const WallNoise n = draw_wall_noise(o, 3, 7, k);
    ASSERT_LE(std::abs(n.rotation_rad), o.rotation_rad);
    ASSERT_LE(n.translation.cwiseAbs().maxCoeff(), o.position);
    largest = std::max(largest, std::abs(n.rotation_rad));
  }
  EXPECT_GT(largest, 0.99 * o.rotation_rad);
}

TEST(PlaneNoise, RigidNoiseRotatesAboutTheMidpointAndKeepsTheLength) {
  WallNoise n;
  n.rotation_rad = 0.2;
  n.translation = {0.1, -0.3};
  const auto [a, b] = n.apply(kA, kB);
  EXPECT_NEAR((b - a).norm(), 4, kRoundoff);
  EXPECT_NEAR((0.5 * (a + b) - (0.5 * (kA + kB) + n.translation)).norm(), 0, kRoundoff);
  EXPECT_NEAR(std::atan2((b - a).y(), (b - a).x()), std::numbers::pi / 2 + 0.2, kRoundoff);
}

TEST(PlaneNoise, EndJitterMovesEachEndAlongTheWall) {
  PlaneNoiseOptions o;
  o.end_sigma = 0.1;
  PlaneNoiseOptions rigid_only = o;
  rigid_only.end_sigma = 0;
  const WallNoise with_ends = draw_wall_noise(o, 5, 2, 11), without = draw_wall_noise(rigid_only, 5, 2, 11);
  // Its own stream: switching the jitter on leaves the rigid part unchanged.
  EXPECT_EQ(with_ends.rotation_rad, without.rotation_rad);
  EXPECT_EQ(with_ends.translation, without.translation);
  EXPECT_NE(with_ends.shift_a, 0.0);
  const auto [a, b] = with_ends.apply(kA, kB);
  const auto [ra, rb] = without.apply(kA, kB);
  EXPECT_NEAR((b - a).norm(), 4 + with_ends.shift_b - with_ends.shift_a, kRoundoff);
  EXPECT_NEAR((b - a).normalized().dot((rb - ra).normalized()), 1, kRoundoff);
}

TEST(PlaneNoise, DrawsArePureFunctionsOfSeedWallAndIteration) {
  const PlaneNoiseOptions o;
  const WallNoise n = draw_wall_noise(o, 1, 2, 3);
  EXPECT_EQ(n.rotation_rad, draw_wall_noise(o, 1, 2, 3).rotation_rad);
  EXPECT_NE(n.rotation_rad, draw_wall_noise(o, 2, 2, 3).rotation_rad);
  EXPECT_NE(n.rotation_rad, draw_wall_noise(o, 1, 3, 3).rotation_rad);
  EXPECT_NE(n.rotation_rad, draw_wall_noise(o, 1, 2, 4).rotation_rad);
}

TEST(PlaneNoise, CheckRejectsNegativeMagnitudes) {
  PlaneNoiseOptions o;
  o.rotation_rad = -kDegree;
  const std::vector<OptionIssue> issues = check(o);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].field, "rotation_deg");
  EXPECT_EQ(issues[0].problem, "must be >= 0, got -1");
}

}  // namespace
}  // namespace relslam::sim
