#include "relslam/sim/figure_eight.hpp"

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include <cmath>

namespace relslam::sim {
namespace {

constexpr double kLength = 1145.0;
constexpr double kIncline = 20.0;

Eigen::Vector2d top_view(const CenterlinePoint& p) { return {p.position.x(), p.position.z()}; }

TEST(FigureEight, RadiusFollowsFromTheLoopLength) {
  // L = 2r(π + π/3) + 4√3 r = 15.30577 r, so r = 74.808 for L = 1145.
  EXPECT_NEAR(FigureEight(kLength, kIncline).radius(), 74.808, 1e-3);
}

TEST(FigureEight, ArcLengthMatchesTheLoopLength) {
  const FigureEight eight(kLength, kIncline);
  constexpr int kSteps = 200000;
  double horizontal = 0;
  for (int i = 0; i < kSteps; ++i)
    horizontal += (top_view(eight.at(kLength * (i + 1) / kSteps)) - top_view(eight.at(kLength * i / kSteps))).norm();
  // Chords under-estimate arcs by ~(ds)^2/(24 r^2) per unit length: far below 1e-6 here.
  EXPECT_NEAR(horizontal, kLength, 1e-6 * kLength);
}

TEST(FigureEight, IsContinuousAndClosed) {
  const FigureEight eight(kLength, kIncline);
  const double ds = 0.01;
  for (double s = 0; s < kLength; s += ds) {
    const double step = (eight.at(s + ds).position - eight.at(s).position).norm();
    ASSERT_LT(step, ds * 1.01) << "jump at s = " << s;
  }
  EXPECT_LT((eight.at(kLength).position - eight.at(0).position).norm(), 1e-9);
}

TEST(FigureEight, InclinePeaksOverTheStartHalfWayRound) {
  const FigureEight eight(kLength, kIncline);
  const CenterlinePoint start = eight.at(0), crossing = eight.at(kLength / 2);
  EXPECT_LT(top_view(crossing).norm(), 1e-9) << "half way round is the crossing";
  EXPECT_NEAR(crossing.position.y() - start.position.y(), kIncline, 1e-12);
  for (double s = 0; s < kLength; s += 1.0) ASSERT_LE(eight.at(s).position.y(), kIncline + 1e-12);
  // The incline must exceed twice the band half height (5) so the passes see disjoint points.
  EXPECT_GT(kIncline, 2 * 5.0);
}

TEST(FigureEight, StartsHeadingDownRightAndTurnsRightLobeFirst) {
  const FigureEight eight(kLength, kIncline);
  // Top view (X, Y) = (x, -z): heading -30°, i.e. right and down (thesis 6.6.1).
  const Eigen::Vector3d t = eight.at(0).tangent;
  EXPECT_NEAR(std::atan2(-t.z(), t.x()), -M_PI / 6, 1e-12);
  EXPECT_GT(eight.at(kLength / 4).position.x(), 0) << "the first lobe is on the right";
  EXPECT_LT(eight.at(3 * kLength / 4).position.x(), 0) << "the second lobe is on the left";
}

TEST(FigureEight, TangentMatchesTheDerivativeAndLeftIsHorizontalNormal) {
  const FigureEight eight(kLength, kIncline);
  for (double s = 0.5; s < kLength; s += 37.3) {
    const CenterlinePoint p = eight.at(s);
    const Eigen::Vector3d derivative = (eight.at(s + 1e-5).position - eight.at(s - 1e-5).position).normalized();
    EXPECT_LT((p.tangent - derivative).norm(), 1e-6) << "s = " << s;
    EXPECT_NEAR(p.tangent.norm(), 1.0, 1e-12);
    EXPECT_NEAR(p.left.norm(), 1.0, 1e-12);
    EXPECT_NEAR(p.left.y(), 0.0, 1e-15);
    EXPECT_NEAR(p.left.dot(p.tangent), 0.0, 1e-12);
    EXPECT_GT(Eigen::Vector3d::UnitY().cross(p.tangent).dot(p.left), 0) << "left is to the left of travel";
  }
}

}  // namespace
}  // namespace relslam::sim
