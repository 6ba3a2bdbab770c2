// Evidence against a place (view_evidence.hpp): from the robot's true place the map contradicts
// nothing it sees; a mapped wall well inside the field of view that is not seen, or a plane in
// view passing through a mapped wall, rules a place out; walls behind the robot's back, facing
// away or hidden by others (with occlusion) are not expected. Relocalisation (pose_integrity.hpp)
// then takes the one place the evidence leaves where two fit the planes in view alike.
#include "relslam/plane/pose_integrity.hpp"
#include "relslam/plane/view_evidence.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <optional>
#include <vector>

namespace relslam::plane {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// A 14 x 10 room, walls facing inwards, and a short wall (2 long) at x = 12, z 7-9, facing -x
// (its normal points to the visible side, PlaneObject): the map (world frame).
std::vector<PlaneObject> room_with_stub() {
  return {{{0, 0}, {14, 0}},   {{14, 0}, {14, 10}}, {{14, 10}, {0, 10}}, {{0, 10}, {0, 0}},
          {{12, 7}, {12, 9}}};
}

bool is_stub(const PlaneObject& p) { return p.length() < 2.5; }

// The thesis's large frustum (half angle 35 degrees, 30 deep), known.
FieldOfView large_view() { return {.known = true, .half_angle_rad = 35 * kDeg, .near = 0.1, .far = 30}; }

// What the plane sensor sees of `walls` from world_T_robot through `view` (no occlusion): each
// front-facing wall's part inside the footprint, found by fine sampling (robot frame).
std::vector<PlaneObject> seen_from(const std::vector<PlaneObject>& walls, const PlanarPose& world_T_robot,
                                   const FieldOfView& view) {
  std::vector<PlaneObject> seen;
  for (const PlaneObject& w : walls) {
    const PlaneObject r = w.transformed(world_T_robot.inverse());
    if (r.offset() <= 0) continue;
    std::optional<double> first, last;
    for (double t = 0; t <= 1.0; t += 1e-4)
      if (view.depth(r.a + t * (r.b - r.a)) >= 0) {
        if (!first) first = t;
        last = t;
      }
    if (first && *last > *first) seen.push_back({r.a + *first * (r.b - r.a), r.a + *last * (r.b - r.a)});
  }
  return seen;
}

ViewConflict conflict(const PlanarPose& pose, const std::vector<PlaneObject>& seen,
                      const std::vector<PlaneObject>& map, const FieldOfView& view) {
  return view_conflict(pose, seen, map, view, ViewEvidenceOptions{}, CoverBounds{});
}

TEST(ViewEvidence, TheTruePlaceIsNotContradicted) {
  const std::vector<PlaneObject> map = room_with_stub();
  for (const PlanarPose& truth : {PlanarPose::from(3, 3, 20 * kDeg), PlanarPose::from(7, 5, 170 * kDeg),
                                  PlanarPose::from(10, 2, 95 * kDeg)}) {
    const std::vector<PlaneObject> seen = seen_from(map, truth, large_view());
    EXPECT_EQ(conflict(truth, seen, map, large_view()), ViewConflict::None);
  }
}

TEST(ViewEvidence, AMappedWallInViewThatIsNotSeenRulesThePlaceOut) {
  const std::vector<PlaneObject> map = room_with_stub();
  const PlanarPose truth = PlanarPose::from(3, 3, 20 * kDeg);  // looking at the far corner and the stub
  std::vector<PlaneObject> seen = seen_from(map, truth, large_view());
  ASSERT_EQ(std::ranges::count_if(seen, is_stub), 1);
  std::erase_if(seen, is_stub);  // the stub not seen: the robot is not where the map has it in view
  EXPECT_EQ(conflict(truth, seen, map, large_view()), ViewConflict::UnseenWall);
  // Unknown field of view: no evidence either way.
  EXPECT_EQ(conflict(truth, seen, map, FieldOfView{}), ViewConflict::None);
}

TEST(ViewEvidence, WallsBehindFacingAwayOrHiddenAreNotExpected) {
  const std::vector<PlaneObject> map = room_with_stub();
  // Looking along -x from x = 13: the stub faces away (-x, the robot is on its back side).
  const PlanarPose behind = PlanarPose::from(13, 5, 180 * kDeg);
  EXPECT_EQ(conflict(behind, seen_from(map, behind, large_view()), map, large_view()), ViewConflict::None);
  // Looking along +x at x = 14 from (10, 5): the wall x = 0 is behind the robot's back.
  const PlanarPose ahead = PlanarPose::from(10, 5, 0);
  std::vector<PlaneObject> seen = seen_from(map, ahead, large_view());
  EXPECT_EQ(conflict(ahead, seen, map, large_view()), ViewConflict::None);
  // A wall hidden behind a longer one: expected without occlusion, not with it.
  const std::vector<PlaneObject> two = {{{5, -3}, {5, 3}}, {{9, -1}, {9, 1}}};  // both facing -x
  const PlanarPose origin = PlanarPose::from(0, 0, 0);
  seen = {two[0]};
  EXPECT_EQ(conflict(origin, seen, two, large_view()), ViewConflict::UnseenWall);
  FieldOfView occluding = large_view();
  occluding.occlusion = true;
  EXPECT_EQ(conflict(origin, seen, two, occluding), ViewConflict::None);
}

TEST(ViewEvidence, APlaneInViewThroughAMappedWallRulesThePlaceOut) {
  const std::vector<PlaneObject> map = room_with_stub();
  const PlanarPose truth = PlanarPose::from(3, 3, 20 * kDeg);
  std::vector<PlaneObject> seen = seen_from(map, truth, large_view());
  // A plane in view that, at this place, would run from inside the room through the wall z = 10.
  seen.push_back(PlaneObject{{8, 8}, {8, 12}}.transformed(truth.inverse()));
  EXPECT_EQ(conflict(truth, seen, map, large_view()), ViewConflict::Crossing);
}

// The room without the stub is symmetric: three walls in view fit two places, turned by 180
// degrees about its centre, and relocalisation takes neither. With the stub on the map, at the
// turned place it would be in view and is not seen: the field of view leaves the true place.
TEST(ViewEvidence, RelocalisationTakesThePlaceTheEvidenceLeaves) {
  const std::vector<PlaneObject> map = room_with_stub();
  // Looking along -x from behind the stub: the wall x = 0 and the far parts of z = 0 and z = 10.
  const PlanarPose truth = PlanarPose::from(12.5, 5, 180 * kDeg);
  const std::vector<PlaneObject> seen = seen_from(map, truth, large_view());
  ASSERT_EQ(seen.size(), 3u);
  ASSERT_EQ(std::ranges::count_if(seen, is_stub), 0);
  IntegrityOptions o;
  EXPECT_FALSE(relocalize(seen, map, std::nullopt, o).has_value());  // two places fit alike
  o.field_of_view = large_view();
  const std::optional<IntegrityResult> found = relocalize(seen, map, std::nullopt, o);
  ASSERT_TRUE(found.has_value());
  EXPECT_NEAR((found->world_T_robot.translation - truth.translation).norm(), 0.0, 1e-9);
  EXPECT_NEAR(wrap_angle(found->world_T_robot.heading - truth.heading), 0.0, 1e-9);
}

}  // namespace
}  // namespace relslam::plane
