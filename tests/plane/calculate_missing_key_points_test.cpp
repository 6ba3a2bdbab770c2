#include "relslam/plane/calculate_missing_key_points.hpp"

#include "clipped_wall_fixture.hpp"
#include "relslam/plane/key_point_compare.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace relslam::plane {
namespace {

using test::ClippedWall;

// The wall the robot passes on its right (see key_point_compare_test.cpp): grows from its real
// left end, whole from t ≈ 47 to 60, then shrinks towards its real right end.
double window_end(int t) { return 1 + 0.15 * t; }
const ClippedWall kPassed{{-1, -6},
                          {7, -6},
                          [](int t) { return std::max(0.0, window_end(t) - 10); },
                          [](int t) { return std::min(8.0, window_end(t)); }};
// Its mirror image on the left of a hallway at z = 0 (normal −z), cut at the same x: with it the
// passed wall is Rule 15's symmetric pair, so that comparison gives no key point.
const ClippedWall kTwin{{7, 0},
                        {-1, 0},
                        [](int t) { return 8 - std::min(8.0, window_end(t)); },
                        [](int t) { return 8 - std::max(0.0, window_end(t) - 10); }};
const ClippedWall kAcross{{4, -5}, {4, 3}, test::constant(0), test::constant(8)};

std::vector<PlaneObject> seen(const ClippedWall& wall, int first = 0, int n = 100) {
  relslam::test::SeededRandom random(1);
  return test::observe_clipped(wall, first, n, {}, random);
}

// Rule 19: the twin leaves it ambiguous, a plane seen only later shares no iteration, the wall
// across gives it — and in each growth phase the end that was real then.
TEST(CalculateMissingKeyPoints, FirstPartnerWithAKeyPointInTheForcedPhaseGivesIt) {
  const std::vector<PlaneObject> passed = seen(kPassed), twin = seen(kTwin), later = seen(kAcross, 200, 20),
                                 across = seen(kAcross);
  const RelativePlaneOptions options;
  ASSERT_TRUE(compare_with_key_points(twin, passed, options, 30).ambiguous);
  const std::vector<ObservationView> others = {twin, later, across};

  const auto growing = calculate_missing_key_points(passed, others, 30, options);
  ASSERT_TRUE(growing);
  EXPECT_EQ(growing->key_point, KeyPoint::Left);
  EXPECT_EQ(growing->partner, 2);

  const auto shrinking = calculate_missing_key_points(passed, others, 90, options);
  ASSERT_TRUE(shrinking);
  EXPECT_EQ(shrinking->key_point, KeyPoint::Right);
  EXPECT_EQ(shrinking->partner, 2);
}

TEST(CalculateMissingKeyPoints, NoneWhenNoPartnerCanTell) {
  const std::vector<PlaneObject> passed = seen(kPassed), twin = seen(kTwin), across = seen(kAcross);
  const RelativePlaneOptions options;
  EXPECT_FALSE(calculate_missing_key_points(passed, {twin}, 30, options));           // ambiguous
  EXPECT_FALSE(calculate_missing_key_points(passed, {across}, 150, options));        // not seen then
  EXPECT_FALSE(calculate_missing_key_points(across, {seen(kAcross)}, 30, options));  // static: no key point needed
  EXPECT_FALSE(calculate_missing_key_points(passed, {}, 30, options));
}

}  // namespace
}  // namespace relslam::plane
