#include "relslam/plane/rlt_xpoints_s.hpp"

#include "plane_world_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <vector>

namespace relslam::plane {
namespace {

constexpr double kPi = std::numbers::pi;
// noise-free runs keep map and pose within 1e-6 wherever the pose is valid.
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

// The final map of a run: each RltPlane's placed ends (NaN when it is not on the map).
std::vector<PlaneObject> final_map(const test::PlaneRun& world, const RelativePlaneOptions& options) {
  RltXPointsS slam(options, world.world_T_robot.front());
  for (const PlaneFrame& frame : world.frames) slam.step(frame);
  std::vector<PlaneObject> out;
  for (const MapPlane& m : slam.map()) out.push_back(m.mapped ? m.plane : PlaneObject::from_pose({}, 0));
  return out;
}

// E31 (Rule 2): the order in which a group's planes are chained does not change a noise-free
// map. Reversing every new group's chain moves its base plane and every edge, yet each plane
// lands on the same place to 1e-9.
TEST(RltXPointsS, E31ReversedChainsGiveTheSameNoiseFreeMap) {
  RelativePlaneOptions reversed;
  reversed.chain_order = ChainOrder::Reversed;
  for (const test::PlaneRun& world :
       {hallway_there_and_back(), test::run_path(test::four_planes_walls(), test::four_planes_path(1, 0.05, 0.03),
                                                 {.always = true})}) {
    const std::vector<PlaneObject> a = final_map(world, {}), b = final_map(world, reversed);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_GE(a.size(), 4u);
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_LT((a[i].a - b[i].a).norm(), 1e-9) << "RltPlane " << i;
      EXPECT_LT((a[i].b - b[i].b).norm(), 1e-9) << "RltPlane " << i;
    }
  }
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

// A robot standing at the origin and walls that come and go by a script (the scripted sensor
// of the hallway unit test, thesis 4.3.2, Fig. 71): each wall faces the origin from direction
// `at_deg`, `distance` away, 2 long, and is seen whole in the iterations of `seen`.
struct ScriptedWall {
  double at_deg;
  double distance;
  std::vector<std::pair<int, int>> seen;  // first..last, both included
};

std::vector<PlaneFrame> scripted_frames(const std::vector<ScriptedWall>& script, int iterations) {
  std::vector<PlaneFrame> frames;
  for (int t = 0; t < iterations; ++t) {
    std::vector<test::Wall> visible;
    for (const ScriptedWall& w : script) {
      if (std::ranges::none_of(w.seen, [t](const auto& s) { return s.first <= t && t <= s.second; })) continue;
      const double at = w.at_deg * kPi / 180;
      const Eigen::Vector2d centre = w.distance * Eigen::Vector2d(std::cos(at), std::sin(at));
      const Eigen::Vector2d along(-std::sin(at), std::cos(at));  // front normal towards the origin
      visible.push_back({centre - along, centre + along});
    }
    frames.push_back(test::observe(visible, PlanarPose{}, t, {.always = true}));
  }
  return frames;
}

// Thesis 4.3.2, Fig. 73 (E06), Rule 12: X0 = {A, B, C, D} is made at iteration 4; C and D leave
// the view; a briefly seen S makes the short-lived group X1 = {A, B, S}, linked by A and B, and
// X1 is the working group. Then A and B leave, C and D come back (Rule 11 takes them back) and
// a new plane Q appears with them. X1 cannot give Q two linking planes seen with it (Rules 8,
// 9); only X0 can, by C and D.
constexpr int kA = 0, kB = 1, kC = 2, kD = 3, kS = 4, kQ = 5;  // RltPlane ids, by first sighting
const std::vector<ScriptedWall> kShortLivedGroup = {
    {-90, 5, {{0, 34}}},          // A
    {-30, 4, {{0, 34}}},          // B
    {30, 5, {{0, 9}, {35, 70}}},  // C
    {90, 4, {{0, 9}, {35, 70}}},  // D
    {150, 5, {{10, 25}}},         // S
    {210, 4, {{40, 70}}},         // Q
};

// Part 1 (key_points off): full-size planes, no Rule 22 charting, no Rule 21 regrouping.
RelativePlaneOptions part1() {
  RelativePlaneOptions options;
  options.key_points = false;
  return options;
}

TEST(RltXPointsS, Rule12TraversalLinksANewGroupPastAShortLivedWorkingGroup) {
  const std::vector<PlaneFrame> frames = scripted_frames(kShortLivedGroup, 71);
  RelativePlaneOptions off = part1();
  off.rules.traverse_to_link = false;
  RltXPointsS with(part1()), without(off);
  for (const PlaneFrame& frame : frames) {
    const RelativePlaneStep step = with.step(frame);
    without.step(frame);
    ASSERT_EQ(step.assignment.size(), frame.planes.size());
    if (frame.iteration >= 35) {  // the planes seen again are the old RltPlanes (Rule 11), both runs
      EXPECT_TRUE(std::ranges::all_of(step.assignment, [](PlaneId p) { return p <= kQ; }));
    }
  }
  for (const RltXPointsS* slam : {&with, &without}) {
    ASSERT_EQ(slam->planes().size(), 6u);
    ASSERT_GE(slam->links().size(), 2u);
    EXPECT_EQ(slam->xpoints()[0].planes(), (std::vector<PlaneId>{kA, kB, kC, kD}));
    EXPECT_EQ(slam->xpoints()[1].planes(), (std::vector<PlaneId>{kA, kB, kS}));
    EXPECT_EQ(slam->links()[1].from, 0);
    EXPECT_EQ(slam->links()[1].planes, (std::vector<PlaneId>{kA, kB}));
  }
  // On: the traversal passes X1 and links X2 = {C, D, Q} to X0 by C and D, at Q's fifth reading.
  ASSERT_EQ(with.links().size(), 3u);
  const RltXPointLink& link = with.links()[2];
  EXPECT_EQ(link.from, 0);
  EXPECT_EQ(link.to, 2);
  EXPECT_EQ(link.created_iteration, 44);
  EXPECT_EQ((std::set<PlaneId>(link.planes.begin(), link.planes.end())), (std::set<PlaneId>{kC, kD}));
  EXPECT_EQ(with.xpoints()[2].planes(), (std::vector<PlaneId>{kC, kD, kQ}));
  ASSERT_TRUE(with.map()[kQ].mapped);
  EXPECT_TRUE(with.unassigned().empty());
  // Off: only the working group X1 is tried, and it fails every iteration: Q gets no group and
  // never reaches the map.
  EXPECT_EQ(without.links().size(), 2u);
  EXPECT_EQ(without.xpoints().size(), 2u);
  EXPECT_EQ(without.unassigned(), (std::vector<PlaneId>{kQ}));
  EXPECT_TRUE(kQ >= static_cast<PlaneId>(without.map().size()) || !without.map()[kQ].mapped);
}

TEST(RltXPointsS, Rule12LinkPlacesTheNewPlaneExactly) {
  const std::vector<PlaneFrame> frames = scripted_frames(kShortLivedGroup, 71);
  RltXPointsS slam;
  double worst = 0;
  for (const PlaneFrame& frame : frames) {
    const RelativePlaneStep step = slam.step(frame);
    ASSERT_TRUE(step.pose_valid || frame.iteration < 4) << frame.iteration;
    if (!step.pose_valid) continue;
    worst = std::max({worst, step.world_T_robot.translation.norm(), std::abs(step.world_T_robot.heading)});
    for (std::size_t i = 0; i < step.assignment.size(); ++i) {
      const MapPlane& mapped = step.map[step.assignment[i]];
      if (!mapped.mapped) continue;  // robot at the origin: the map is what it sees
      worst =
          std::max({worst, (mapped.plane.a - frame.planes[i].a).norm(), (mapped.plane.b - frame.planes[i].b).norm()});
    }
  }
  EXPECT_LT(worst, kNoiseFree);
  EXPECT_TRUE(slam.map()[kQ].mapped);
}

// Part 1 (options.key_points off) has no Rule 22 charting (thesis 4.3.5 ff.): the current group
// is the one last created (thesis 4.3.2 [R]: a new group becomes the working group), and it stays
// current when the robot is back among an older group's planes only.
TEST(RltXPointsS, CurrentGroupIsTheGroupLastCreated) {
  const std::vector<PlaneFrame> frames = scripted_frames(kShortLivedGroup, 71);
  RltXPointsS slam(part1());
  for (const PlaneFrame& frame : frames) {
    const RelativePlaneStep step = slam.step(frame);
    const int t = frame.iteration;
    const XPointId expected = t < 4 ? kNone : t < 14 ? 0 : t < 44 ? 1 : 2;
    EXPECT_EQ(step.current_group, expected) << "iteration " << t;
    EXPECT_EQ(slam.current_xpoint(), step.current_group);
    if (!step.groups.empty()) {
      EXPECT_EQ(step.current_group, step.groups.back().id());
    }
  }
}

TEST(RltXPointsS, HallwayReturnLegKeepsTheLastGroupCurrent) {
  const test::PlaneRun world = hallway_there_and_back();
  RltXPointsS slam(part1(), world.world_T_robot.front());
  const int turn_end = 360 + 36;  // MOVE 36 by 0.1, TURN 180° by 5°
  XPointId at_turn = kNone;
  for (const PlaneFrame& frame : world.frames) {
    const RelativePlaneStep step = slam.step(frame);
    if (!step.groups.empty()) {
      EXPECT_EQ(step.current_group, step.groups.back().id());
    }
    if (frame.iteration == turn_end) at_turn = step.current_group;
  }
  // On the way back no plane is new (Rule 11), so no group is made and the last one stays
  // current although the robot ends among X0's planes.
  EXPECT_EQ(slam.current_xpoint(), at_turn);
  EXPECT_EQ(slam.current_xpoint(), static_cast<XPointId>(slam.xpoints().size()) - 1);
  EXPECT_NE(slam.current_xpoint(), 0);
}

// Rule 22 (parts 2 and 3, options.key_points): the current group is the one holding most of the
// planes in view (RltXPointChart). Back among X0's planes at the end of the return leg it is X0,
// not the group last started; with the rule off the last one stays current.
TEST(RltXPointsS, Rule22MakesTheGroupHoldingThePlanesInViewCurrent) {
  const test::PlaneRun world = hallway_there_and_back();
  RelativePlaneOptions options;
  options.key_points = true;
  RltXPointsS slam(options, world.world_T_robot.front());
  RelativePlaneStep last;
  for (const PlaneFrame& frame : world.frames) last = slam.step(frame);
  std::vector<int> held(slam.xpoints().size(), 0);
  for (PlaneId p : last.assignment)
    for (const RltXPointRef& ref : slam.planes()[p].refs()) ++held[ref.xpoint];
  EXPECT_EQ(held[slam.current_xpoint()], *std::ranges::max_element(held));
  EXPECT_NE(slam.current_xpoint(), static_cast<XPointId>(slam.xpoints().size()) - 1);

  options.rules.current_group_chart = false;
  RltXPointsS off(options, world.world_T_robot.front());
  for (const PlaneFrame& frame : world.frames) off.step(frame);
  EXPECT_EQ(off.current_xpoint(), static_cast<XPointId>(off.xpoints().size()) - 1);
}

// Rule 21 (options.key_points): the walls global matching re-acquires on the return leg start
// groups of their own — more groups — and the noise-free map stays exact; the cap of
// memberships (K_xrefs) limits how many.
TEST(RltXPointsS, Rule21GivesReacquiredPlanesGroupsOfTheirOwn) {
  const test::PlaneRun world = hallway_there_and_back();
  RelativePlaneOptions options;
  options.key_points = true;
  RelativePlaneOptions off = options;
  off.rules.regroup_reacquired = false;
  RelativePlaneOptions capped = options;
  capped.regroup_memberships = 1;  // every re-acquired plane already has one group
  const RunSummary with = run(test::hallway_walls(), world, options);
  const RunSummary without = run(test::hallway_walls(), world, off);
  const RunSummary none = run(test::hallway_walls(), world, capped);
  EXPECT_GT(with.global_matches, 0);
  EXPECT_GT(with.groups, without.groups);
  EXPECT_EQ(none.groups, without.groups);
  EXPECT_LT(with.worst_pose, 1e-9);
  EXPECT_LT(with.worst_map, 1e-9);
  EXPECT_EQ(with.rlt_planes, with.walls_seen);
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
  slam.step(PlaneFrame{3, {}, nullptr, {}});
  EXPECT_THROW(slam.step(PlaneFrame{3, {}, nullptr, {}}), std::logic_error);
}

TEST(RltXPointsS, InvalidOptionsAreABug) {
  RelativePlaneOptions bad;
  bad.min_readings = 0;
  EXPECT_THROW(RltXPointsS{bad}, std::logic_error);
}

}  // namespace
}  // namespace relslam::plane
