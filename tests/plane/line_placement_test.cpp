// Walls and groups placed by the walls' lines (relative_plane.place_by_lines, line_placement.hpp):
// a wall seen in pieces lying on one line is placed on that line, exactly without noise, and
// covers every piece; pieces off the line place nothing; a group is placed exactly on two walls
// in two directions, and not on parallel walls or walls it does not lie on.
#include "relslam/plane/line_placement.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace relslam::plane {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// A piece of the wall through (1, 2) at 30 degrees, from s0 to s1 along it.
PlaneObject piece(double s0, double s1, double across = 0) {
  const Eigen::Vector2d u(std::cos(30 * kDeg), std::sin(30 * kDeg)), n(-u.y(), u.x());
  const Eigen::Vector2d origin = Eigen::Vector2d(1, 2) + across * n;
  PlaneObject p;
  p.a = origin + s0 * u;
  p.b = origin + s1 * u;
  p.a_cut = p.b_cut = true;  // every end cut: no group can compare it (Rules 13-15)
  return p;
}

double distance_to_line(const PlaneObject& line, const Eigen::Vector2d& x) {
  return std::abs(line.normal().dot(x) + line.offset());
}

TEST(LinePlacement, PiecesOnOneLinePlaceTheWallOnItCoveringEveryPiece) {
  LinePlacementOptions options;
  options.samples = 3;
  LinePlacement placement;
  add_line_evidence(placement, piece(0, 1), options);
  add_line_evidence(placement, piece(0.5, 2), options);
  EXPECT_FALSE(placement.placed);  // two samples of three
  add_line_evidence(placement, piece(1.5, 3), options);
  ASSERT_TRUE(placement.placed);
  EXPECT_NEAR(placement.world.angle(), 30 * kDeg, 1e-12);
  EXPECT_NEAR(distance_to_line(placement.world, {1, 2}), 0, 1e-12);
  EXPECT_NEAR(placement.world.length(), 3, 1e-12);
  EXPECT_NEAR((placement.world.a - piece(0, 1).a).norm(), 0, 1e-12);
  // A later piece on the line lengthens it; one beside the line does not.
  add_line_evidence(placement, piece(2.5, 4.5), options);
  EXPECT_NEAR(placement.world.length(), 4.5, 1e-12);
  add_line_evidence(placement, piece(5, 7, 0.5), options);
  EXPECT_NEAR(placement.world.length(), 4.5, 1e-12);
}

TEST(LinePlacement, PiecesOffOneLinePlaceNothing) {
  LinePlacementOptions options;
  options.samples = 3;
  LinePlacement placement;
  add_line_evidence(placement, piece(0, 1), options);
  add_line_evidence(placement, piece(0.5, 2, 0.3), options);  // 0.3 across: a different wall
  add_line_evidence(placement, piece(1.5, 3), options);
  EXPECT_FALSE(placement.placed);
  // The window moves on: three that agree place it.
  add_line_evidence(placement, piece(2, 3), options);
  add_line_evidence(placement, piece(2.5, 3.5), options);
  EXPECT_TRUE(placement.placed);
}

// A group whose planes, in its own frame, are two walls of the map in two directions.
TEST(LinePlacement, GroupPlacedExactlyOnTwoWallsInTwoDirections) {
  const PlanarPose world_T_group = PlanarPose::from(3, -1, 40 * kDeg);
  const PlaneObject wall1 = piece(0, 4), wall2{{6, 0}, {6, 5}};
  // The group saw pieces of them, elsewhere along the walls than the map has them.
  const PlaneObject in_group1 = piece(5, 6).transformed(world_T_group.inverse());
  const PlaneObject in_group2 = PlaneObject{{6, 6}, {6, 7}}.transformed(world_T_group.inverse());
  const LinePlacementOptions options;
  const std::vector<LinePair> pairs = {{in_group1, wall1}, {in_group2, wall2}};
  const std::optional<PlanarPose> placed = place_on_lines(pairs, options);
  ASSERT_TRUE(placed.has_value());
  EXPECT_NEAR((placed->translation - world_T_group.translation).norm(), 0, 1e-9);
  EXPECT_NEAR(wrap_angle(placed->heading - world_T_group.heading), 0, 1e-12);
  // Parallel walls leave it free along them.
  const std::vector<LinePair> parallel = {{in_group1, wall1}, {piece(0, 1, 3).transformed(world_T_group.inverse()), piece(0, 1, 3)}};
  EXPECT_FALSE(place_on_lines(parallel, options).has_value());
  // A third plane that does not lie on its wall there: not placed.
  const PlaneObject off = piece(0, 2, 1).transformed(world_T_group.inverse());
  const std::vector<LinePair> three = {{in_group1, wall1}, {in_group2, wall2}, {off, piece(0, 2, 1.4)}};
  EXPECT_FALSE(place_on_lines(three, options).has_value());
}

}  // namespace
}  // namespace relslam::plane
