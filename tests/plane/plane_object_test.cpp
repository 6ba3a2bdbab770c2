#include "relslam/plane/plane_object.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace relslam::plane {
namespace {

constexpr double kExact = 1e-12;  // noise-free algebra: only rounding

// A wall 3 ahead of the robot, 4 long, facing it (normal −x), seen at iteration 10.
PlaneObject wall_ahead() { return {{3, -2}, {3, 2}, 0.0, 2.5, 10}; }

PlaneObject moved(const PlaneObject& p, const PlanarPose& new_T_old, int iteration) {
  PlaneObject out = p.transformed(new_T_old);
  out.iteration = iteration;
  return out;
}

TEST(MatchPlane, SameWallOnTheNextIterationMatches) {
  const PlaneObject previous = wall_ahead();
  // The robot moved 0.05 forward and turned 1.5°: the wall shifts a little in its frame.
  const PlanarPose robot_motion = PlanarPose::from(0.05, 0, 1.5 * std::numbers::pi / 180);
  const PlaneObject current = moved(previous, robot_motion.inverse(), 11);
  const double score = match_plane(previous, current, MatchBounds{});
  EXPECT_GT(score, 50);
  EXPECT_LT(score, 100);
}

TEST(MatchPlane, IdenticalObservationScoresAllButTheGapPoints) {
  PlaneObject current = wall_ahead();
  current.iteration = 11;
  const MatchBounds bounds;
  // Normal, offset and box are perfect; one iteration of gap costs 25/(c_gap + 1).
  EXPECT_NEAR(match_plane(wall_ahead(), current, bounds), 100 - 25.0 / (bounds.max_iteration_gap + 1), kExact);
}

TEST(MatchPlane, OppositeNormalIsAnotherPlaneUnderRule10) {
  PlaneObject back = wall_ahead();
  std::swap(back.a, back.b);  // the same segment seen from behind: the normal flips
  back.iteration = 11;
  EXPECT_EQ(match_plane(wall_ahead(), back, MatchBounds{}), -1);
  // Rule 10 off: the flipped normal matches (the Fig 72 problem).
  EXPECT_GT(match_plane(wall_ahead(), back, MatchBounds{}, false), 0);
}

TEST(MatchPlane, GapLongerThanTheBoundFails) {
  const MatchBounds bounds;
  PlaneObject current = wall_ahead();
  current.iteration = 10 + bounds.max_iteration_gap;
  EXPECT_GT(match_plane(wall_ahead(), current, bounds), 0);
  current.iteration = 10 + bounds.max_iteration_gap + 1;
  EXPECT_EQ(match_plane(wall_ahead(), current, bounds), -1);
  // Global matching has no iteration test.
  EXPECT_GT(match_plane(wall_ahead(), current, global_match_defaults()), 0);
}

TEST(MatchPlane, CollinearNeighbourSegmentIsRejectedByTheOverlapRule) {
  // The next segment of the same wall after a gap of 0.3: normal, offset and the widened
  // boxes all agree, only the overlap along the plane does not.
  const PlaneObject previous = wall_ahead();  // z from −2 to 2
  const PlaneObject neighbour{{3, 2.3}, {3, 6.3}, 0.0, 2.5, 11};
  EXPECT_EQ(match_plane(previous, neighbour, MatchBounds{}), -1);
  MatchBounds no_overlap_rule;
  no_overlap_rule.min_overlap_fraction = -10;
  EXPECT_GT(match_plane(previous, neighbour, no_overlap_rule), 0);
}

TEST(MatchPlane, OffsetJumpFails) {
  PlaneObject current = moved(wall_ahead(), PlanarPose::from(1.0, 0, 0), 11);  // 1 unit farther
  EXPECT_EQ(match_plane(wall_ahead(), current, MatchBounds{}), -1);
}

// The sensor's rotation noise turns a plane about its own midpoint. A piece far along
// its wall — 27 units from the foot of the perpendicular, as a far wall in the large frustum —
// turned by 1° moves its offset d by 27·sin 1° = 0.47, past c_d = 0.3; the robot turning by the
// same angle would leave d unchanged. The offset test allows what the angle explains.
TEST(MatchPlane, FarPieceTurnedAboutItsMidpointStillMatches) {
  const PlaneObject previous{{3, 26}, {3, 28}, 0.0, 2.5, 10};
  const PlanarPose turn_about_midpoint =
      PlanarPose::from(3, 27, std::numbers::pi / 180) * PlanarPose::from(-3, -27, 0);
  const PlaneObject current = moved(previous, turn_about_midpoint, 11);
  EXPECT_GT(std::abs(current.offset() - previous.offset()), 0.45);
  EXPECT_GT(match_plane(previous, current, MatchBounds{}), 0);
  MatchBounds thesis;
  thesis.rotation_about_midpoint = false;
  EXPECT_EQ(match_plane(previous, current, thesis), -1);
  // Not a licence for any offset: the same piece 0.5 farther, not turned, still fails.
  const PlaneObject farther = moved(previous, PlanarPose::from(0.5, 0, 0), 11);
  EXPECT_EQ(match_plane(previous, farther, MatchBounds{}), -1);
}

TEST(PlaneObjectOperations, KeyPointsAndAssumedMidpointsFollowRule14) {
  const PlaneObject p = wall_ahead();  // at 0° (normal +z) a = (3, −2) is the left end
  EXPECT_EQ(key_point(p, KeyPoint::Left), p.a);
  EXPECT_EQ(key_point(p, KeyPoint::Right), p.b);
  // Assumed midpoints for a true length of 6: 3 along the plane from each end.
  EXPECT_LT((assumed_midpoint(p, 6, KeyPoint::Left) - Eigen::Vector2d(3, 1)).norm(), kExact);
  EXPECT_LT((assumed_midpoint(p, 6, KeyPoint::Right) - Eigen::Vector2d(3, -1)).norm(), kExact);
  EXPECT_THROW(key_point(p, KeyPoint::None), std::logic_error);
}

TEST(PlaneObjectOperations, AdjustSizeKeepsTheKeyPointEnd) {
  const PlaneObject p = wall_ahead();
  const PlaneObject from_left = adjust_size(p, 6, KeyPoint::Left);
  EXPECT_EQ(from_left.a, p.a);
  EXPECT_LT((from_left.b - Eigen::Vector2d(3, 4)).norm(), kExact);
  const PlaneObject from_right = adjust_size(p, 1, KeyPoint::Right);
  EXPECT_EQ(from_right.b, p.b);
  EXPECT_LT((from_right.a - Eigen::Vector2d(3, 1)).norm(), kExact);
  EXPECT_NEAR(from_right.angle(), p.angle(), kExact);
  EXPECT_THROW(adjust_size(p, 6, KeyPoint::None), std::logic_error);
}

TEST(PlaneObjectOperations, CalculateOffsetRecoversAKnownRobotPose) {
  const PlaneObject world_wall{{-4, -5}, {4, -5}};
  for (const PlanarPose& truth :
       {PlanarPose::from(-2, -2, 0), PlanarPose::from(1.5, 3, 2.5), PlanarPose::from(0.3, -1, -3.1)}) {
    const PlaneObject seen = world_wall.transformed(truth.inverse());
    const PlanarPose found = calculate_offset(world_wall, seen);
    EXPECT_LT((found.translation - truth.translation).norm(), kExact);
    EXPECT_NEAR(wrap_angle(found.heading - truth.heading), 0, kExact);
  }
}

}  // namespace
}  // namespace relslam::plane
