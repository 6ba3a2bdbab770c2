#include "relslam/plane/rlt_xpoints_s.hpp"

#include "plane_world_fixture.hpp"

#include <gtest/gtest.h>

#include <map>
#include <numbers>
#include <set>
#include <vector>

namespace relslam::plane {
namespace {

constexpr double kPi = std::numbers::pi;
// Spec §8: noise-free runs keep map and pose within 1e-6 wherever the pose is valid.
constexpr double kNoiseFree = 1e-6;

struct RunSummary {
  int valid_poses = 0;
  double worst_pose = 0;
  double worst_map = 0;
  int rlt_planes = 0;
  int walls_seen = 0;
  int groups = 0;
  int links = 0;
  int global_matches = 0;
  bool one_wall_per_plane = true;
  std::vector<int> first_valid;  // iterations of the first valid pose
};

// Runs the algorithm over a fixture run and scores it against the walls at every iteration.
RunSummary run(const std::vector<test::Wall>& walls, const test::PlaneRun& world,
               const RelativePlaneOptions& options = {}) {
  RltXPointsS slam(options, world.world_T_robot.front());
  RunSummary summary;
  std::map<PlaneId, int> wall_of;
  std::set<int> walls_seen;
  for (std::size_t t = 0; t < world.frames.size(); ++t) {
    const RelativePlaneStep step = slam.step(world.frames[t]);
    for (std::size_t i = 0; i < step.assignment.size(); ++i) {
      const int wall = world.wall_ids[t][i];
      walls_seen.insert(wall);
      const auto [it, inserted] = wall_of.emplace(step.assignment[i], wall);
      if (!inserted && it->second != wall) summary.one_wall_per_plane = false;
    }
    summary.global_matches += step.global_matches;
    if (!step.pose_valid) continue;
    if (summary.valid_poses++ == 0) summary.first_valid.push_back(static_cast<int>(t));
    const PlanarPose& truth = world.world_T_robot[t];
    summary.worst_pose = std::max({summary.worst_pose, (step.world_T_robot.translation - truth.translation).norm(),
                                   std::abs(wrap_angle(step.world_T_robot.heading - truth.heading))});
    for (PlaneId p = 0; p < static_cast<PlaneId>(step.map.size()); ++p) {
      if (!step.map[p].mapped) continue;
      const test::Wall& wall = walls[wall_of.at(p)];
      const PlaneObject& mapped = step.map[p].plane;
      summary.worst_map = std::max({summary.worst_map, (mapped.a - wall.a).norm(), (mapped.b - wall.b).norm()});
    }
  }
  summary.rlt_planes = static_cast<int>(slam.planes().size());
  summary.walls_seen = static_cast<int>(walls_seen.size());
  summary.groups = static_cast<int>(slam.xpoints().size());
  summary.links = static_cast<int>(slam.links().size());
  return summary;
}

// E03 without noise: the four planes problem, Rules 1–5, ten loops of the square path.
TEST(RltXPointsS, FourPlanesNoiseFreeMapAndPoseAreExactAtEveryValidIteration) {
  const std::vector<test::Wall> walls = test::four_planes_walls();
  const test::PlaneRun world = test::run_path(walls, test::four_planes_path(10, 0.1, 5 * kPi / 180), {.always = true});
  const RunSummary s = run(walls, world);
  EXPECT_EQ(s.rlt_planes, 4);
  EXPECT_EQ(s.groups, 1);
  EXPECT_TRUE(s.one_wall_per_plane);
  // The map exists once the planes have min_readings observations (iterations 0–4).
  ASSERT_EQ(s.first_valid.size(), 1u);
  EXPECT_EQ(s.first_valid.front(), RelativePlaneOptions{}.min_readings - 1);
  EXPECT_EQ(s.valid_poses, static_cast<int>(world.frames.size()) - s.first_valid.front());
  EXPECT_LT(s.worst_pose, kNoiseFree);
  EXPECT_LT(s.worst_map, kNoiseFree);
}

// The hallway (Map B/C-like, full size): planes enter and leave, new groups are linked by two
// planes (Rules 6–9, 12); the robot turns at the end and walks back past every plane again.
test::PlaneRun hallway_there_and_back() {
  test::PathBuilder path(PlanarPose::from(0, 0, 0));
  path.move(36, 0.1).turn(kPi, 5 * kPi / 180).move(36, 0.1);
  return test::run_path(test::hallway_walls(), path.poses(), {});
}

TEST(RltXPointsS, HallwayNoiseFreeMapAndPoseAreExactAtEveryValidIteration) {
  const test::PlaneRun world = hallway_there_and_back();
  const RunSummary s = run(test::hallway_walls(), world);
  EXPECT_TRUE(s.one_wall_per_plane);
  EXPECT_GE(s.groups, 4);        // planes came and went
  EXPECT_EQ(s.links, s.groups);  // the first link anchors X0 (Rule 4)
  EXPECT_GT(s.valid_poses, 700);
  EXPECT_LT(s.worst_pose, kNoiseFree);
  EXPECT_LT(s.worst_map, kNoiseFree);
}

TEST(RltXPointsS, Rule11ReturnLegMakesNoDuplicatePlanes) {
  const test::PlaneRun world = hallway_there_and_back();
  const RunSummary with = run(test::hallway_walls(), world);
  EXPECT_EQ(with.rlt_planes, with.walls_seen);
  EXPECT_GT(with.global_matches, 0);
  RelativePlaneOptions off;
  off.rules.global_matching = false;
  const RunSummary without = run(test::hallway_walls(), world, off);
  EXPECT_GT(without.rlt_planes, without.walls_seen);  // the walls seen again become new planes
  EXPECT_EQ(without.global_matches, 0);
}

TEST(RltXPointsS, HallwayGroupsAreLinkedByTwoPlanesSeenLatest) {
  const test::PlaneRun world = hallway_there_and_back();
  RltXPointsS slam({}, world.world_T_robot.front());
  for (const PlaneFrame& frame : world.frames) slam.step(frame);
  ASSERT_FALSE(slam.links().empty());
  EXPECT_TRUE(slam.links().front().first);
  for (std::size_t k = 1; k < slam.links().size(); ++k) {
    const RltXPointLink& link = slam.links()[k];
    ASSERT_EQ(link.planes.size(), 2u) << "link " << k;  // Rule 8
    const RltXPoint& from = slam.xpoints()[link.from];
    for (PlaneId l : link.planes) {
      EXPECT_NE(slam.planes()[l].ref(link.from), nullptr);
      EXPECT_NE(slam.planes()[l].ref(link.to), nullptr);
    }
    // Rule 9: every other plane of `from` in view when the link was made, and seen long
    // enough to be a candidate, was first seen no later than the linking planes.
    const int t = link.created_iteration;
    const int oldest_link =
        std::min(slam.planes()[link.planes[0]].created_iteration(), slam.planes()[link.planes[1]].created_iteration());
    for (PlaneId p : from.planes()) {
      const RltPlane& plane = slam.planes()[p];
      const bool candidate = plane.get_plane(t) != nullptr && plane.created_iteration() <= t - 10;
      if (candidate && std::ranges::find(link.planes, p) == link.planes.end()) {
        EXPECT_LE(plane.created_iteration(), oldest_link) << "link " << k << " plane " << p;
      }
    }
  }
}

TEST(RltXPointsS, HallwayStaysExactWithGroupIntervalsOrOneLinkingPlane) {
  const test::PlaneRun world = hallway_there_and_back();
  RelativePlaneOptions group_mode;
  group_mode.interval_mode = IntervalMode::Group;  // Fig 74's choice
  RelativePlaneOptions one_link;
  one_link.rules.two_linking_planes = false;  // Rule 8 off
  for (const RelativePlaneOptions& options : {group_mode, one_link}) {
    const RunSummary s = run(test::hallway_walls(), world, options);
    EXPECT_LT(s.worst_pose, kNoiseFree);
    EXPECT_LT(s.worst_map, kNoiseFree);
    EXPECT_EQ(s.rlt_planes, s.walls_seen);
  }
  RltXPointsS slam(one_link, world.world_T_robot.front());
  for (const PlaneFrame& frame : world.frames) slam.step(frame);
  for (std::size_t k = 1; k < slam.links().size(); ++k) EXPECT_EQ(slam.links()[k].planes.size(), 1u);
}

TEST(RltXPointsS, WithoutRule3TheFourPlanesMapBreaksOnceTheRobotTurns) {
  const std::vector<test::Wall> walls = test::four_planes_walls();
  const test::PlaneRun world = test::run_path(walls, test::four_planes_path(1, 0.1, 5 * kPi / 180), {.always = true});
  RelativePlaneOptions raw;
  raw.rules.rotate_to_first = false;
  EXPECT_GT(run(walls, world, raw).worst_map, 0.1);
  EXPECT_LT(run(walls, world).worst_map, kNoiseFree);
}

TEST(RltXPointsS, WithoutRule4TheMapStaysInTheFrameOfTheFirstGroupsBasePlane) {
  const std::vector<test::Wall> walls = test::four_planes_walls();
  const test::PlaneRun world = test::run_path(walls, test::four_planes_path(1, 0.1, 5 * kPi / 180), {.always = true});
  RelativePlaneOptions unanchored;
  unanchored.rules.anchor_first_observation = false;
  RltXPointsS slam(unanchored, world.world_T_robot.front());
  for (const PlaneFrame& frame : world.frames) slam.step(frame);
  const MapPlane& base = slam.map()[slam.xpoints().front().planes().front()];
  ASSERT_TRUE(base.mapped);
  EXPECT_LT(base.world_T_plane.translation.norm(), 1e-12);
  EXPECT_NEAR(base.world_T_plane.heading, 0, 1e-12);
}

TEST(RltXPointsS, SameInputGivesTheSameRun) {
  const test::PlaneRun world = hallway_there_and_back();
  RltXPointsS a({}, world.world_T_robot.front()), b({}, world.world_T_robot.front());
  for (const PlaneFrame& frame : world.frames) {
    const RelativePlaneStep sa = a.step(frame), sb = b.step(frame);
    ASSERT_EQ(sa.pose_valid, sb.pose_valid);
    ASSERT_EQ(sa.world_T_robot.translation, sb.world_T_robot.translation);
    ASSERT_EQ(sa.world_T_robot.heading, sb.world_T_robot.heading);
    ASSERT_TRUE(std::ranges::equal(sa.assignment, sb.assignment));
  }
  EXPECT_EQ(a.xpoints().size(), b.xpoints().size());
}

TEST(RltXPointsS, IterationsMustIncrease) {
  RltXPointsS slam;
  slam.step(PlaneFrame{3, {}});
  EXPECT_THROW(slam.step(PlaneFrame{3, {}}), std::logic_error);
}

TEST(RltXPointsS, InvalidOptionsAreABug) {
  RelativePlaneOptions bad;
  bad.min_readings = 0;
  EXPECT_THROW(RltXPointsS{bad}, std::logic_error);
}

}  // namespace
}  // namespace relslam::plane
