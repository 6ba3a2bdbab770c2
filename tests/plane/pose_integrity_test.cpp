// Pose integrity and relocalisation (the adaptive preset, pose_integrity.hpp): the pose from
// the planes' lines is exact noise-free, a pose resting on parallel planes or on a wrong
// registration is refused with its reason, and a lost robot is found again on the whole map.
#include "relslam/plane/pose_integrity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace relslam::plane {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// An L-shaped room with walls at 30 and 120 degrees: the map (world) and what a robot at
// world_T_robot sees of it (robot frame), whole walls.
std::vector<PlaneObject> room() {
  const PlanarPose world_T_room = PlanarPose::from(2, 1, 30 * kDeg);
  const std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> local = {
      {{0.5, 0}, {13.5, 0}}, {{14, 0.5}, {14, 9.5}}, {{13.5, 10}, {0.5, 10}}, {{0, 9.5}, {0, 0.5}}, {{5, 5}, {9, 5}}};
  std::vector<PlaneObject> out;
  for (const auto& [a, b] : local) out.push_back({world_T_room * a, world_T_room * b});
  return out;
}

PlaneObject seen_from(const PlaneObject& world, const PlanarPose& world_T_robot) {
  return world.transformed(world_T_robot.inverse());
}

std::vector<LinePair> pairs_from(const std::vector<PlaneObject>& map, const std::vector<int>& walls,
                                 const PlanarPose& world_T_robot) {
  std::vector<LinePair> out;
  for (int w : walls) out.push_back({seen_from(map[w], world_T_robot), map[w]});
  return out;
}

void expect_pose(const PlanarPose& got, const PlanarPose& want, double tolerance) {
  EXPECT_NEAR((got.translation - want.translation).norm(), 0.0, tolerance);
  EXPECT_NEAR(wrap_angle(got.heading - want.heading), 0.0, tolerance);
}

TEST(PoseIntegrity, TwoNonParallelPlanesGiveTheExactPose) {
  const std::vector<PlaneObject> map = room();
  const PlanarPose truth = PlanarPose::from(6.3, 4.1, 47 * kDeg);
  const IntegrityResult r = check_pose(pairs_from(map, {0, 1}, truth), IntegrityOptions{});
  ASSERT_TRUE(r.valid);
  EXPECT_EQ(r.reason, PoseReason::Lines);
  expect_pose(r.world_T_robot, truth, 1e-9);
}

TEST(PoseIntegrity, ParallelPlanesDoNotFixThePose) {
  const std::vector<PlaneObject> map = room();
  const IntegrityResult r = check_pose(pairs_from(map, {0, 2, 4}, PlanarPose::from(6, 3, 0.2)), IntegrityOptions{});
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.reason, PoseReason::OneDirection);
  EXPECT_EQ(check_pose({}, IntegrityOptions{}).reason, PoseReason::NoPlanes);
}

TEST(PoseIntegrity, APlantedWrongRegistrationIsMarkedInvalid) {
  // The robot sees walls 0 and 1, but wall 1's observation is registered to wall 3 (the
  // opposite wall, same direction as the map has it turned round): two lines always fit a pose,
  // so the check must catch it by direction, distance or overlap.
  const std::vector<PlaneObject> map = room();
  const PlanarPose truth = PlanarPose::from(7, 5, 10 * kDeg);
  std::vector<LinePair> pairs = pairs_from(map, {0, 1}, truth);
  pairs[1].mapped = map[3];
  EXPECT_FALSE(check_pose(pairs, IntegrityOptions{}).valid);
  // The inner wall registered to the outer wall it is parallel to: the two lines fit a pose 5
  // off along wall 1, and wall 1, seen whole, no longer lies within its map plane.
  pairs = pairs_from(map, {1, 4}, truth);
  pairs[1].mapped = map[0];
  const IntegrityResult r = check_pose(pairs, IntegrityOptions{});
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.reason, PoseReason::Disagree);
  // Where every plane in view still fits (wall 1 seen only as a piece, 2 long, near its middle),
  // the robot's motion since the last valid pose (an iteration ago, at the truth) tells.
  pairs[0].seen = seen_from(PlaneObject{map[1].a + 5.5 * map[1].tangent(), map[1].a + 7.5 * map[1].tangent()}, truth);
  EXPECT_TRUE(check_pose(pairs, IntegrityOptions{}).valid);
  const IntegrityResult jump = check_pose(pairs, IntegrityOptions{}, std::pair{truth, 1});
  EXPECT_FALSE(jump.valid);
  EXPECT_EQ(jump.reason, PoseReason::Jump);
  // The inner wall (4 long) registered to a map plane 6 further along its line: the lines fit,
  // but the two do not overlap, so the check refuses it without any history.
  pairs = pairs_from(map, {1, 4}, truth);
  pairs[1].mapped = PlaneObject{map[4].a + 6 * map[4].tangent(), map[4].b + 6 * map[4].tangent()};
  pairs[1].seen = seen_from(map[4], truth);
  const IntegrityResult shifted = check_pose(pairs, IntegrityOptions{});
  EXPECT_FALSE(shifted.valid);
  EXPECT_EQ(shifted.reason, PoseReason::Disagree);
  // With a third plane in view the wrong one is outvoted and dropped: the pose is right.
  pairs = pairs_from(map, {0, 1, 4}, truth);
  pairs[2].mapped = map[2];
  const IntegrityResult outvoted = check_pose(pairs, IntegrityOptions{});
  ASSERT_TRUE(outvoted.valid);
  EXPECT_EQ(outvoted.planes, 2);
  expect_pose(outvoted.world_T_robot, truth, 1e-9);
}

TEST(PoseIntegrity, APoseFurtherThanTheRobotCanMoveIsAJump) {
  const std::vector<PlaneObject> map = room();
  const PlanarPose truth = PlanarPose::from(7, 5, 10 * kDeg);
  const std::vector<LinePair> pairs = pairs_from(map, {0, 1}, truth);
  const IntegrityOptions o;
  EXPECT_TRUE(check_pose(pairs, o, std::pair{PlanarPose::from(7.1, 5, 0.2), 1}).valid);
  const IntegrityResult r = check_pose(pairs, o, std::pair{PlanarPose::from(9, 5, 0.2), 1});
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.reason, PoseReason::Jump);
  // Lost long enough, the last valid pose no longer binds.
  EXPECT_TRUE(check_pose(pairs, o, std::pair{PlanarPose::from(9, 5, 0.2), o.continuity_window + 1}).valid);
}

TEST(PoseIntegrity, RelocalisationFindsTheLostRobotOnTheWholeMap) {
  const std::vector<PlaneObject> map = room();
  const PlanarPose truth = PlanarPose::from(9.5, 8.0, 100 * kDeg);
  std::vector<PlaneObject> seen;
  for (int w : {1, 2, 4}) seen.push_back(seen_from(map[w], truth));
  // Lost for a while: the robot is within 3 of where it was last seen.
  const NearPose reach{PlanarPose::from(8, 6, 80 * kDeg), 3.0};
  const std::optional<IntegrityResult> found = relocalize(seen, map, reach, IntegrityOptions{});
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(found->reason, PoseReason::Recovered);
  EXPECT_EQ(found->planes, 3);
  expect_pose(found->world_T_robot, truth, 1e-9);
  // Where the robot can be limits the search: the truth lies outside a reach of 1 from (2, 2).
  EXPECT_FALSE(relocalize(seen, map, NearPose{PlanarPose::from(2, 2, 0), 1.0}, IntegrityOptions{}).has_value());
  // Two walls of a corner fit every corner of the room: never a guess.
  seen = {seen_from(map[0], truth), seen_from(map[1], truth)};
  EXPECT_FALSE(relocalize(seen, map, std::nullopt, IntegrityOptions{}).has_value());
  // Nothing in two directions: nothing to find.
  EXPECT_FALSE(relocalize(std::vector<PlaneObject>{seen[0]}, map, std::nullopt, IntegrityOptions{}).has_value());
  // A symmetric room (the square of walls 0-3 without the inner wall): three walls fit two
  // places, turned by 180 degrees about the centre, and neither is taken.
  const std::vector<PlaneObject> square(map.begin(), map.begin() + 4);
  seen = {seen_from(map[0], truth), seen_from(map[1], truth), seen_from(map[2], truth)};
  EXPECT_FALSE(relocalize(seen, square, std::nullopt, IntegrityOptions{}).has_value());
  EXPECT_TRUE(relocalize(seen, square, reach, IntegrityOptions{}).has_value());
}

// A plane in view that Rule 1 still tracks on a map plane keeps it: the symmetric room's two
// places become one, and a place where the tracked plane does not agree is none.
TEST(PoseIntegrity, RelocalisationKeepsTheMapPlaneRule1Tracks) {
  const std::vector<PlaneObject> map = room();
  const std::vector<PlaneObject> square(map.begin(), map.begin() + 4);
  const PlanarPose truth = PlanarPose::from(9.5, 8.0, 100 * kDeg);
  const std::vector<PlaneObject> seen = {seen_from(map[0], truth), seen_from(map[1], truth), seen_from(map[2], truth)};
  const std::vector<int> tracked = {0, -1, -1};
  const std::optional<IntegrityResult> found = relocalize(seen, square, std::nullopt, IntegrityOptions{}, tracked);
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(found->planes, 3);
  expect_pose(found->world_T_robot, truth, 1e-9);
  // Tracked on the wall across the room: only the place turned by 180 degrees has it there.
  const std::optional<IntegrityResult> turned = relocalize(seen, square, std::nullopt, IntegrityOptions{}, std::vector<int>{2, -1, -1});
  ASSERT_TRUE(turned.has_value());
  EXPECT_GT((turned->world_T_robot.translation - truth.translation).norm(), 1.0);
  // Tracked on a wall it cannot lie on at any place that fits the others: nothing.
  EXPECT_FALSE(relocalize(seen, square, std::nullopt, IntegrityOptions{}, std::vector<int>{1, -1, -1}).has_value());
}

}  // namespace
}  // namespace relslam::plane
