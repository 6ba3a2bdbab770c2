#include "relslam/sim/viewing_frustum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace relslam::sim {
namespace {

// Clip ends are computed as a + t·(b − a): exact up to a few ulps of the coordinates.
constexpr double kEndTolerance = 1e-12;
const double kTan30 = std::tan(30.0 * std::numbers::pi / 180.0);

// The visible piece's ends, for comparing against hand-computed geometry.
struct Piece {
  Eigen::Vector2d a, b;
  bool cut_a, cut_b;
};
Piece seen(const ViewingFrustum& f, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const std::optional<SegmentClip> clip = f.clip(a, b);
  EXPECT_TRUE(clip.has_value()) << "segment " << a.transpose() << " -> " << b.transpose() << " is not seen";
  if (!clip) return {a, a, false, false};
  return {a + clip->enter * (b - a), a + clip->exit * (b - a), clip->cuts_a(), clip->cuts_b()};
}

void expect_point(const Eigen::Vector2d& actual, const Eigen::Vector2d& expected) {
  EXPECT_NEAR(actual.x(), expected.x(), kEndTolerance) << actual.transpose() << " vs " << expected.transpose();
  EXPECT_NEAR(actual.y(), expected.y(), kEndTolerance) << actual.transpose() << " vs " << expected.transpose();
}

TEST(ViewingFrustum, PresetsAreTheSpecsSmallAndLargeAndValid) {
  const ViewingFrustum small = ViewingFrustum::small(), large = ViewingFrustum::large();
  EXPECT_EQ(small.shape, FrustumShape::Planar);
  EXPECT_DOUBLE_EQ(small.half_angle_rad, 30.0 * std::numbers::pi / 180.0);
  EXPECT_EQ(small.near, 0.1);
  EXPECT_EQ(small.far, 7.0);
  EXPECT_DOUBLE_EQ(large.half_angle_rad, 35.0 * std::numbers::pi / 180.0);
  EXPECT_EQ(large.far, 30.0);
  EXPECT_TRUE(check(small).empty());
  EXPECT_TRUE(check(large).empty());
  EXPECT_EQ(frustum_preset("large")->far, 30.0);
  EXPECT_FALSE(frustum_preset("medium"));
}

TEST(ViewingFrustum, WallAcrossTheViewIsCutOnBothSideEdges) {
  for (FrustumShape shape : {FrustumShape::Planar, FrustumShape::Radial}) {
    ViewingFrustum f;
    f.shape = shape;
    const Piece p = seen(f, {5, -10}, {5, 10});
    expect_point(p.a, {5, -5 * kTan30});
    expect_point(p.b, {5, 5 * kTan30});
    EXPECT_TRUE(p.cut_a && p.cut_b) << to_string(shape);
  }
}

TEST(ViewingFrustum, PlanarTrapezoidReachesFartherAtTheSidesThanTheRadialSector) {
  // Along z = 3: the side edge at x = 3/tan 30°; the planar far line at x = 7, the radial far
  // circle at x = √(49 − 9) (thesis 4.4.2: the trapezoid's corners lie beyond `far`).
  ViewingFrustum planar;
  const Piece p = seen(planar, {0, 3}, {10, 3});
  expect_point(p.a, {3 / kTan30, 3});
  expect_point(p.b, {7, 3});
  ViewingFrustum radial;
  radial.shape = FrustumShape::Radial;
  const Piece r = seen(radial, {0, 3}, {10, 3});
  expect_point(r.a, {3 / kTan30, 3});
  expect_point(r.b, {std::sqrt(40.0), 3});
  EXPECT_TRUE(r.cut_a && r.cut_b);
}

TEST(ViewingFrustum, NearLineCutsAWallThroughTheRobot) {
  const Piece p = seen(ViewingFrustum::small(), {-1, 0}, {3, 0});
  expect_point(p.a, {0.1, 0});
  EXPECT_EQ(p.b, Eigen::Vector2d(3, 0)) << "an uncut end is the segment's own end";
  EXPECT_TRUE(p.cut_a);
  EXPECT_FALSE(p.cut_b);
}

TEST(ViewingFrustum, SegmentInsideIsUncut) {
  for (FrustumShape shape : {FrustumShape::Planar, FrustumShape::Radial}) {
    ViewingFrustum f;
    f.shape = shape;
    const std::optional<SegmentClip> clip = f.clip({4, -1}, {5, 1});
    ASSERT_TRUE(clip);
    EXPECT_EQ(clip->enter, 0.0);
    EXPECT_EQ(clip->exit, 1.0);
  }
}

TEST(ViewingFrustum, SegmentsOutsideAreNotSeen) {
  for (FrustumShape shape : {FrustumShape::Planar, FrustumShape::Radial}) {
    ViewingFrustum f;
    f.shape = shape;
    EXPECT_FALSE(f.clip({-5, -3}, {-5, 3})) << "behind the robot";
    EXPECT_FALSE(f.clip({8, -1}, {8, 1})) << "beyond far";
    EXPECT_FALSE(f.clip({1, 2}, {3, 4})) << "left of the view";
    EXPECT_FALSE(f.clip({6.9, 4.5}, {6.9, 6})) << "outside the side edge near the far corner";
  }
  ViewingFrustum radial;
  radial.shape = FrustumShape::Radial;
  EXPECT_FALSE(radial.clip({6.5, 3.5}, {6.8, 3.6})) << "inside the trapezoid's corner, beyond the radial range";
  EXPECT_TRUE(ViewingFrustum().clip({6.5, 3.5}, {6.8, 3.6}));
}

TEST(ViewingFrustum, LargeRadialCutsAtTheFarCircle) {
  ViewingFrustum f = ViewingFrustum::large();
  f.shape = FrustumShape::Radial;
  const Piece p = seen(f, {10, 10}, {40, 10});  // along z = 10: enters at the edge, leaves at |p| = 30
  const double tan35 = std::tan(35.0 * std::numbers::pi / 180.0);
  expect_point(p.a, {10 / tan35, 10});
  expect_point(p.b, {std::sqrt(800.0), 10});
}

TEST(ViewingFrustum, ContainsAgreesWithClippingASinglePoint) {
  for (FrustumShape shape : {FrustumShape::Planar, FrustumShape::Radial}) {
    ViewingFrustum f;
    f.shape = shape;
    int inside = 0;
    for (double x = -1; x <= 8; x += 0.25)
      for (double z = -5; z <= 5; z += 0.25) {
        const Eigen::Vector2d p(x, z);
        EXPECT_EQ(f.contains(p), f.clip(p, p).has_value()) << to_string(shape) << " " << p.transpose();
        inside += f.contains(p);
      }
    EXPECT_GT(inside, 100);
  }
}

TEST(ViewingFrustum, CheckRejectsAnOpenOrInvertedFootprint) {
  ViewingFrustum f;
  f.half_angle_rad = std::numbers::pi / 2;
  f.near = 8;
  const std::vector<OptionIssue> issues = check(f);
  ASSERT_EQ(issues.size(), 2u);
  EXPECT_EQ(issues[0].field, "half_angle_deg");
  EXPECT_EQ(issues[0].problem, "must be > 0 and < 90, got 90");
  EXPECT_EQ(issues[1].field, "far");
  EXPECT_EQ(issues[1].problem, "must be > near (8), got 7");
}

// depth(): the distance to the footprint's nearest edge, negative outside (what marks an
// extracted wall's end as cut by the field of view).
TEST(ViewingFrustum, DepthIsTheDistanceToTheNearestEdge) {
  const ViewingFrustum small = ViewingFrustum::small();  // 30 degrees half angle, near 0.1, far 7
  EXPECT_NEAR(small.depth({3.5, 0.0}), 3.5 * std::sin(30.0 * std::numbers::pi / 180.0), 1e-12);  // the sides
  EXPECT_NEAR(small.depth({6.5, 0.0}), 0.5, 1e-12);                                                // far
  EXPECT_NEAR(small.depth({0.15, 0.0}), 0.05, 1e-12);                                               // near
  EXPECT_NEAR(small.depth({2.0, 2.0 * std::tan(30.0 * std::numbers::pi / 180.0)}), 0.0, 1e-12);   // on a side
  EXPECT_NEAR(small.depth({8.0, 0.0}), -1.0, 1e-12);                                               // beyond far
  EXPECT_LT(small.depth({3.0, -3.0}), 0.0);
  // The radial frustum's far edge is the circle.
  ViewingFrustum radial = small;
  radial.shape = FrustumShape::Radial;
  EXPECT_NEAR(radial.depth({6.0, 0.5}), 7.0 - std::hypot(6.0, 0.5), 1e-12);
  // depth >= 0 exactly where contains() holds.
  for (double x = -1; x <= 9; x += 0.37)
    for (double z = -6; z <= 6; z += 0.41) EXPECT_EQ(small.depth({x, z}) >= 0, small.contains({x, z})) << x << " " << z;
}

}  // namespace
}  // namespace relslam::sim
