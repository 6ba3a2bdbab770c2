#include "relslam/plane/key_point_compare.hpp"

#include "clipped_wall_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace relslam::plane {
namespace {

constexpr double kExact = 1e-9;

using test::ClippedWall;

// A wall across the view, always seen whole.
const ClippedWall kAcross{{4, -5}, {4, 3}, test::constant(0), test::constant(8)};

// A wall of length 8 along the right that the robot passes: a 10-long window c(t) − 10 .. c(t)
// slides along it, c = 1 + 0.15 t. It grows from its real left end until t ≈ 47, is whole until
// t = 60, then shrinks towards its real right end (t ≤ 99: length 2.15).
ClippedWall passed_wall() {
  const auto c = [](int t) { return 1 + 0.15 * t; };
  return {
      {-1, -6}, {7, -6}, [=](int t) { return std::max(0.0, c(t) - 10); }, [=](int t) { return std::min(8.0, c(t)); }};
}

std::vector<PlaneObject> seen(const ClippedWall& wall, int first = 0, int n = 100) {
  relslam::test::SeededRandom random(1);
  return test::observe_clipped(wall, first, n, {}, random);
}

void expect_pose_near(const PlanarPose& actual, const PlanarPose& expected, double tolerance) {
  EXPECT_LT((actual.translation - expected.translation).norm(), tolerance)
      << "got (" << actual.translation.transpose() << "), expected (" << expected.translation.transpose() << ")";
  EXPECT_NEAR(wrap_angle(actual.heading - expected.heading), 0, tolerance);
}

// Rule 18 then Rule 13: the growing piece (the longer) gives the real left end, at full size.
TEST(CompareWithKeyPoints, PassedWallIsComparedOverItsGrowingPieceWithKeyPoint1) {
  const ClippedWall passed = passed_wall();
  const CompareResult r = compare_with_key_points(seen(kAcross), seen(passed), RelativePlaneOptions{});
  ASSERT_TRUE(r.valid);
  EXPECT_EQ(r.interval.start, 0);
  // The split lies on the plateau (t 47..60), widened by the window.
  EXPECT_GE(r.interval.end, 47 - 5);
  EXPECT_LE(r.interval.end, 60 + 5);
  EXPECT_GT(r.samples, 50);
  EXPECT_TRUE(r.static1);
  EXPECT_EQ(r.key_point1, KeyPoint::None);
  EXPECT_EQ(r.key_point2, KeyPoint::Left);
  EXPECT_FALSE(r.static2 || r.ambiguous);
  EXPECT_NEAR(r.length2, 8, kExact);
  expect_pose_near(r.delta, test::anchored_delta(kAcross, 8, KeyPoint::Left, passed, 8, KeyPoint::Left), kExact);
}

// Rule 19's forced interval: an iteration in the shrinking piece gives the real right end.
TEST(CompareWithKeyPoints, ForcedIterationInTheShrinkingPieceGivesKeyPoint2) {
  const ClippedWall passed = passed_wall();
  const CompareResult r = compare_with_key_points(seen(kAcross), seen(passed), RelativePlaneOptions{}, 90);
  ASSERT_TRUE(r.valid);
  EXPECT_EQ(r.interval.end, 99);
  EXPECT_EQ(r.key_point2, KeyPoint::Right);
  EXPECT_NEAR(r.length2, 8, kExact);  // the piece starts on the plateau
  expect_pose_near(r.delta, test::anchored_delta(kAcross, 8, KeyPoint::Left, passed, 8, KeyPoint::Right), kExact);
}

// Without the split (hysteresis beyond any change) each end of the passed wall moves during
// part of the interval: no pair is constant and the offset is wrong — why Rule 18 exists.
TEST(CompareWithKeyPoints, WithoutTheSplitTheOffsetOfAPassedWallIsWrong) {
  RelativePlaneOptions no_split;
  no_split.growth_phase.hysteresis = 1e9;
  no_split.trim_piece_ends = false;  // the thesis's plain split
  const ClippedWall passed = passed_wall();
  const CompareResult r = compare_with_key_points(seen(kAcross), seen(passed), no_split);
  ASSERT_TRUE(r.valid);
  EXPECT_EQ(r.samples, 100);
  const PlanarPose truth = test::anchored_delta(kAcross, 8, KeyPoint::Left, passed, 8, KeyPoint::Left);
  EXPECT_GT((r.delta.translation - truth.translation).norm(), 0.5);
}

// A wall first seen as a middle piece (cut at both ends by the frustum's far corner, Fig 105),
// then with its real right end while it shrinks from the left: its length falls throughout, so
// Rule 18 does not split, and the first sample's cut right end would sit in the average. Its
// offset stands off the series of the real ends: the piece is trimmed and the offset is exact.
TEST(CompareWithKeyPoints, AFirstSampleCutAtTheRealEndIsTrimmedFromThePiece) {
  const ClippedWall leaving{{-1, -6},
                            {7, -6},
                            [](int t) { return t == 0 ? 2.5 : 3 + 0.1 * t; },
                            [](int t) { return t == 0 ? 7.9 : 8.0; }};
  const std::vector<PlaneObject> first = seen(kAcross, 0, 12), second = seen(leaving, 0, 12);
  ASSERT_GT(second[0].length(), second[1].length());  // shrinking from the first sample on
  const CompareResult r = compare_with_key_points(first, second, RelativePlaneOptions{});
  ASSERT_TRUE(r.valid);
  EXPECT_EQ(r.interval.start, 1);
  EXPECT_EQ(r.samples, 11);
  EXPECT_EQ(r.key_point2, KeyPoint::Right);
  expect_pose_near(r.delta, test::anchored_delta(kAcross, 8, KeyPoint::Left, leaving, r.length2, KeyPoint::Right),
                   kExact);

  RelativePlaneOptions plain;
  plain.trim_piece_ends = false;
  const CompareResult untrimmed = compare_with_key_points(first, second, plain);
  EXPECT_EQ(untrimmed.samples, 12);
  const PlanarPose truth =
      test::anchored_delta(kAcross, 8, KeyPoint::Left, leaving, untrimmed.length2, KeyPoint::Right);
  EXPECT_GT((untrimmed.delta.translation - truth.translation).norm(), 0.005);
}

// A wall seen only as a middle piece, cut at both ends (the small frustum's far corner sweeping it
// in during a turn, Fig 105; Map D's iterations 718–720): no pair of ends keeps its offset. The
// thesis compares it anyway and places the wall wrong; rigid_sigma calls the comparison invalid,
// and leaves a rigid pair alone.
TEST(CompareWithKeyPoints, APieceCutAtBothEndsIsInvalidWithRigidSigma) {
  const ClippedWall middle{{-1, -6}, {7, -6}, [](int t) { return 2 + 0.3 * t; }, [](int t) { return 4 + 0.6 * t; }};
  const std::vector<PlaneObject> first = seen(kAcross, 0, 3), second = seen(middle, 0, 3);
  const CompareResult thesis = compare_with_key_points(first, second, RelativePlaneOptions{});
  ASSERT_TRUE(thesis.valid);
  EXPECT_GT(thesis.sigma, 0.05);

  RelativePlaneOptions rigid;
  rigid.rigid_sigma = 1e-6;
  EXPECT_FALSE(compare_with_key_points(first, second, rigid).valid);
  const CompareResult passed = compare_with_key_points(seen(kAcross), seen(passed_wall()), rigid);
  ASSERT_TRUE(passed.valid);
  EXPECT_LT(passed.sigma, 1e-9);
}

// The adaptive preset with relative_plane.open_cut_ends: the sensor's cut-end flags are used.
RelativePlaneOptions open_cut_ends() {
  RelativePlaneOptions o = preset_options(Preset::Adaptive);
  o.open_cut_ends = true;
  return o;
}

// A corridor's two sides, each seen from its real near end (coming towards the robot as it
// drives on) to the far edge of the frustum, which cuts both at the same place (a mirrored
// corridor): in the robot frame the two cut ends stay put together and the two real ends move
// together, so Rule 15 ties the diagonals and the thesis finds no key point. With open_cut_ends
// the adaptive preset knows from the sensor which ends are cut (PlaneObject::a_cut, b_cut) and
// takes the real ones; without it (the default) it compares as the thesis does.
TEST(CompareWithKeyPoints, MirroredCutEndsAreNotKeyPointsWithOpenCutEnds) {
  std::vector<PlaneObject> left, right;
  for (int t = 0; t < 30; ++t) {
    const double near = 2 - 0.1 * t;
    left.push_back({{7, 1.5}, {near, 1.5}, 0, 2.5, t, true, false});     // a cut by the far edge
    right.push_back({{near, -1.5}, {7, -1.5}, 0, 2.5, t, false, true});  // b cut by the far edge
  }
  const CompareResult thesis = compare_with_key_points(left, right, RelativePlaneOptions{});
  ASSERT_TRUE(thesis.valid);
  EXPECT_TRUE(thesis.ambiguous) << "Rule 15's tie: the pair of cut ends looks as static as the real one";

  const CompareResult by_default = compare_with_key_points(left, right, preset_options(Preset::Adaptive));
  ASSERT_TRUE(by_default.valid);
  EXPECT_TRUE(by_default.ambiguous) << "open_cut_ends is off by default";

  const CompareResult adaptive = compare_with_key_points(left, right, open_cut_ends());
  ASSERT_TRUE(adaptive.valid);
  EXPECT_FALSE(adaptive.ambiguous);
  EXPECT_EQ(adaptive.key_point1, KeyPoint::Right);
  EXPECT_EQ(adaptive.key_point2, KeyPoint::Left);
  EXPECT_LT(adaptive.sigma, kExact);
  // The real ends face each other across the corridor: 3 apart, the second turned by 180°.
  const PlanarPose real_ends = adaptive.pair_delta[1][0];
  const Eigen::Vector2d ends = real_ends.translation + Eigen::Vector2d(-0.5 * adaptive.length1, 0) -
                               0.5 * adaptive.length2 * Eigen::Vector2d(std::cos(real_ends.heading), std::sin(real_ends.heading));
  EXPECT_LT((ends - Eigen::Vector2d(0, 3)).norm(), kExact) << ends.transpose();
}

// A piece cut at both ends throughout places nothing with open_cut_ends: no pair of real ends.
TEST(CompareWithKeyPoints, APieceCutAtBothEndsPlacesNothingWithOpenCutEnds) {
  std::vector<PlaneObject> across, middle;
  for (int t = 0; t < 20; ++t) {
    across.push_back({{4, -5}, {4, 3}, 0, 2.5, t});
    middle.push_back({{-1 + 0.1 * t, -6}, {5 + 0.1 * t, -6}, 0, 2.5, t, true, true});
  }
  EXPECT_TRUE(compare_with_key_points(across, middle, RelativePlaneOptions{}).valid);
  EXPECT_TRUE(compare_with_key_points(across, middle, preset_options(Preset::Adaptive)).valid);
  EXPECT_FALSE(compare_with_key_points(across, middle, open_cut_ends()).valid);
}

TEST(CompareWithKeyPoints, InvalidWithoutEnoughCommonIterations) {
  const ClippedWall passed = passed_wall();
  EXPECT_FALSE(compare_with_key_points(seen(kAcross, 0, 50), seen(passed, 50, 50), RelativePlaneOptions{}).valid);
  EXPECT_FALSE(compare_with_key_points(seen(kAcross, 0, 52), seen(passed, 50, 50), RelativePlaneOptions{}).valid);
  const CompareResult three =
      compare_with_key_points(seen(kAcross, 0, 53), seen(passed, 50, 50), RelativePlaneOptions{});
  EXPECT_TRUE(three.valid);  // n_min_cmp = 3
  EXPECT_EQ(three.samples, 3);
  EXPECT_FALSE(compare_with_key_points(seen(kAcross), seen(passed), RelativePlaneOptions{}, 150).valid);
}

}  // namespace
}  // namespace relslam::plane
