// Rules 31–34: hints, the stored inputs and checkpoints, and RltXPointsS's roll-back and replay
// (thesis 4.3.7.2, 4.4.3.15–17, walkthrough 4.5).
#include "relslam/plane/hints.hpp"
#include "relslam/plane/roll_back.hpp"
#include "relslam/plane/rlt_xpoints_s.hpp"

#include "plane_world_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <vector>

namespace relslam::plane {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(RltTemporalHints, AddingAHintDeletesTheLaterOnes) {
  RltTemporalHints hints;
  const PlaneIdentity p{10, 0}, q{12, 1};
  hints.add({HintLevel::NotInX, p, 50, 0});
  hints.add({HintLevel::NotInX, q, 80, 1});
  hints.add({HintLevel::NoExistingX, p, 80, 0});  // the same iteration stays
  EXPECT_EQ(hints.all().size(), 3u);
  EXPECT_EQ(hints.count_for(p), 2);
  hints.add({HintLevel::NotInX, q, 40, 2});  // earlier than both
  ASSERT_EQ(hints.all().size(), 1u);
  EXPECT_EQ(hints.all().front().iteration, 40);
  EXPECT_EQ(hints.count_for(p), 0);
  EXPECT_EQ(hints.count_for(q), 1);
}

TEST(RltTemporalHints, EachLevelForbidsWhatItSaysFromItsIterationOn) {
  const PlaneIdentity p{10, 0}, other{10, 1};
  RltTemporalHints not_in_x;
  not_in_x.add({HintLevel::NotInX, p, 50, 3});
  EXPECT_TRUE(not_in_x.may_join(p, 49, 3));  // before its iteration: no effect
  EXPECT_FALSE(not_in_x.may_join(p, 50, 3));
  EXPECT_FALSE(not_in_x.may_join(p, 500, 3));
  EXPECT_TRUE(not_in_x.may_join(p, 50, 4));  // another group
  EXPECT_TRUE(not_in_x.may_start_group(p, 50));
  EXPECT_TRUE(not_in_x.may_join(other, 50, 3));  // another plane

  RltTemporalHints no_existing;
  no_existing.add({HintLevel::NoExistingX, p, 50, 3});
  EXPECT_FALSE(no_existing.may_join(p, 60, 4));
  EXPECT_TRUE(no_existing.may_start_group(p, 60));

  RltTemporalHints not_on_map;
  not_on_map.add({HintLevel::NotOnMap, p, 50, 3});
  EXPECT_FALSE(not_on_map.may_join(p, 60, 4));
  EXPECT_FALSE(not_on_map.may_start_group(p, 60));
  EXPECT_TRUE(not_on_map.may_start_group(p, 49));
}

TEST(RltPlaneStorage, FindsTheNewestCheckpointBeforeATargetAndTrimsToTheReach) {
  RltPlaneStorage storage;
  RltXPointsState state;
  for (int k = 0; k <= 100; ++k) {
    storage.record({k, {}, nullptr, {}});
    state.iteration_ = k;
    storage.checkpoint_if_due(k, state, 10);
  }
  EXPECT_EQ(storage.checkpoints(), 11u);  // 0, 10, ..., 100
  ASSERT_NE(storage.newest_at_or_before(37), nullptr);
  EXPECT_EQ(storage.newest_at_or_before(37)->iteration, 30);
  EXPECT_EQ(storage.newest_at_or_before(37)->state.iteration_, 30);
  EXPECT_EQ(storage.newest_at_or_before(-1), nullptr);
  EXPECT_EQ(storage.frame_after(37)->iteration, 38);
  EXPECT_EQ(storage.frame_after(100), nullptr);

  // A roll-back to 100 − 45 = 55 restores the end of 54: the checkpoint at 50 must stay.
  storage.trim(100, 45);
  ASSERT_NE(storage.oldest(), nullptr);
  EXPECT_EQ(storage.oldest()->iteration, 50);
  EXPECT_EQ(storage.frame_after(0)->iteration, 51);  // the replay from 50 starts at 51
  storage.drop_after(70);
  EXPECT_EQ(storage.newest_at_or_before(100)->iteration, 70);
}

// The hallway of Map B/C (full size), there and back: groups come and go, Rule 11 re-acquires.
test::PlaneRun hallway_there_and_back() {
  test::PathBuilder path(PlanarPose::from(0, 0, 0));
  path.move(36, 0.1).turn(kPi, 5 * kPi / 180).move(36, 0.1);
  return test::run_path(test::hallway_walls(), path.poses(), {});
}

// Everything step() reports, copied (the spans die with the next step).
struct StepCopy {
  PlanarPose pose;
  bool pose_valid = false;
  int pose_planes = 0;
  std::vector<PlaneId> assignment;
  std::vector<PlaneObject> map;
  std::vector<bool> mapped;
  std::vector<std::vector<PlaneId>> groups;
  std::vector<PlanarPose> group_poses;
  std::size_t links = 0;
  XPointId current = kNone;
  int new_planes = 0, local_matches = 0, global_matches = 0, groups_created = 0, planes_grouped = 0;
};

StepCopy copy_of(const RelativePlaneStep& s) {
  StepCopy c;
  c.pose = s.world_T_robot;
  c.pose_valid = s.pose_valid;
  c.pose_planes = s.pose_planes;
  c.assignment.assign(s.assignment.begin(), s.assignment.end());
  for (const MapPlane& m : s.map) {
    c.map.push_back(m.plane);
    c.mapped.push_back(m.mapped);
  }
  for (const RltXPoint& x : s.groups) {
    c.groups.push_back(x.planes());
    c.group_poses.push_back(x.world_pose());
  }
  c.links = s.links.size();
  c.current = s.current_group;
  c.new_planes = s.new_planes;
  c.local_matches = s.local_matches;
  c.global_matches = s.global_matches;
  c.groups_created = s.groups_created;
  c.planes_grouped = s.planes_grouped;
  return c;
}

bool same_pose(const PlanarPose& a, const PlanarPose& b) {
  return a.translation == b.translation && a.heading == b.heading;  // bit for bit
}

// Every step of two runs is the same, bit for bit.
void expect_same_runs(const std::vector<StepCopy>& want, const std::vector<StepCopy>& got) {
  ASSERT_EQ(want.size(), got.size());
  for (std::size_t t = 0; t < want.size(); ++t) {
    const StepCopy &a = want[t], &b = got[t];
    SCOPED_TRACE(::testing::Message() << "iteration " << t);
    ASSERT_EQ(a.pose_valid, b.pose_valid);
    ASSERT_TRUE(same_pose(a.pose, b.pose));
    ASSERT_EQ(a.pose_planes, b.pose_planes);
    ASSERT_EQ(a.assignment, b.assignment);
    ASSERT_EQ(a.mapped, b.mapped);
    for (std::size_t p = 0; p < a.map.size(); ++p) {
      ASSERT_EQ(a.map[p].a, b.map[p].a) << "plane " << p;
      ASSERT_EQ(a.map[p].b, b.map[p].b) << "plane " << p;
    }
    ASSERT_EQ(a.groups, b.groups);
    for (std::size_t x = 0; x < a.group_poses.size(); ++x) ASSERT_TRUE(same_pose(a.group_poses[x], b.group_poses[x]));
    ASSERT_EQ(a.links, b.links);
    ASSERT_EQ(a.current, b.current);
    ASSERT_EQ(std::tie(a.new_planes, a.local_matches, a.global_matches, a.groups_created, a.planes_grouped),
              std::tie(b.new_planes, b.local_matches, b.global_matches, b.groups_created, b.planes_grouped));
  }
}

struct Outcome {
  std::vector<StepCopy> steps;
  RollBackCounts counts;
  std::vector<RollBackEvent> log;
  std::vector<RltTemporalHint> hints;
};

// `before_step(slam, t)` may ask for roll-backs before step t.
Outcome run(const test::PlaneRun& world, const RelativePlaneOptions& options, auto before_step) {
  RltXPointsS slam(options, world.world_T_robot.front());
  Outcome out;
  for (std::size_t t = 0; t < world.frames.size(); ++t) {
    before_step(slam, static_cast<int>(t));
    const RelativePlaneStep step = slam.step(world.frames[t]);
    out.steps.push_back(copy_of(step));
    out.counts.hints += step.roll_back.hints;
    out.counts.rollbacks += step.roll_back.rollbacks;
    out.counts.refused += step.roll_back.refused;
    out.counts.replayed_iterations += step.roll_back.replayed_iterations;
  }
  out.log = slam.roll_back_log();
  out.hints = slam.hints().all();
  return out;
}
Outcome run(const test::PlaneRun& world, const RelativePlaneOptions& options) {
  return run(world, options, [](RltXPointsS&, int) {});
}

RelativePlaneOptions with_key_points() {
  RelativePlaneOptions o;
  o.key_points = true;
  return o;
}

//, roll-back idempotence: a roll-back with no hint restores an earlier state and replays
// the stored inputs; every step after it is the step the run without it had, bit for bit. Forced
// every 37 iterations 25 back (so replays start from checkpoints before and after the target),
// part 1 and parts 2–3, on the hallway there and back (groups made and re-acquired during a
// replay) and the four planes.
TEST(RltXPointsS, ForcedRollBacksWithoutHintReplayTheSameRunBitForBit) {
  const std::vector<test::PlaneRun> worlds = {
      hallway_there_and_back(),
      test::run_path(test::four_planes_walls(), test::four_planes_path(2, 0.1, 5 * kPi / 180), {.always = true})};
  for (const RelativePlaneOptions& base : {RelativePlaneOptions{}, with_key_points()}) {
    for (const test::PlaneRun& world : worlds) {
      RelativePlaneOptions forced = base;
      forced.rollback.force_every = 37;
      forced.rollback.force_depth = 25;
      forced.rollback.checkpoint_period = 20;
      const Outcome plain = run(world, base), replayed = run(world, forced);
      expect_same_runs(plain.steps, replayed.steps);
      const int n = static_cast<int>(world.frames.size());
      EXPECT_EQ(replayed.counts.rollbacks, (n - 1) / 37);
      EXPECT_EQ(replayed.counts.refused, 0);
      EXPECT_EQ(replayed.counts.hints, 0);
      // Each replays from the checkpoint before its target: 25 to 25 + one period.
      for (const RollBackEvent& e : replayed.log) {
        EXPECT_EQ(e.outcome, RollBackOutcome::Replayed);
        EXPECT_GE(e.replayed_iterations, 26);
        EXPECT_LE(e.replayed_iterations, 26 + 20);
      }
    }
  }
}

// The same with the interval checks on: a roll-back asked for from outside (request_roll_back)
// replays with the hints the run holds and gives the same run as without it.
TEST(RltXPointsS, RequestedRollBackWithIntervalChecksReplaysTheSameRun) {
  const test::PlaneRun world = hallway_there_and_back();
  RelativePlaneOptions options = with_key_points();
  options.rules.interval_check = true;
  const Outcome plain = run(world, options);
  const Outcome replayed = run(world, options, [](RltXPointsS& slam, int t) {
    if (t == 300 || t == 301 || t == 650) slam.request_roll_back(t - 120);
  });
  expect_same_runs(plain.steps, replayed.steps);
  EXPECT_EQ(replayed.counts.rollbacks, plain.counts.rollbacks + 3);
}

// thesis 4.3.7.2: a roll-back further back than the oldest state kept is refused and counted, and
// the run goes on as if it had not been asked for.
TEST(RltXPointsS, RollBackOlderThanTheOldestCheckpointIsRefusedAndCounted) {
  const test::PlaneRun world = hallway_there_and_back();
  RelativePlaneOptions options;
  options.rollback.force_every = 1000000;  // keeps the history, never fires
  options.rollback.force_depth = 0;
  options.rollback.max_depth = 100;
  options.rollback.checkpoint_period = 50;
  const Outcome plain = run(world, options);
  const Outcome refused = run(world, options, [](RltXPointsS& slam, int t) {
    if (t == 500) slam.request_roll_back(300);  // 200 back: the oldest checkpoint is 350–400
    if (t == 600) slam.request_roll_back(520);  // within reach
  });
  expect_same_runs(plain.steps, refused.steps);
  EXPECT_EQ(refused.counts.refused, 1);
  EXPECT_EQ(refused.counts.rollbacks, 1);
  ASSERT_EQ(refused.log.size(), 2u);
  EXPECT_EQ(refused.log[0].outcome, RollBackOutcome::TooOld);
  EXPECT_EQ(refused.log[0].target_iteration, 300);
  EXPECT_EQ(refused.log[0].replayed_iterations, 0);
  EXPECT_EQ(refused.log[1].outcome, RollBackOutcome::Replayed);

  // Without any history kept (no interval checks, nothing forced) every request is refused.
  const Outcome none = run(world, {}, [](RltXPointsS& slam, int t) {
    if (t == 500) slam.request_roll_back(499);
  });
  EXPECT_EQ(none.counts.refused, 1);
  EXPECT_EQ(none.counts.rollbacks, 0);
}

// A constructed case for Rule 32 (full-size planes, a robot at 0.5 a step along +x): walls A and
// B line the way and are seen throughout (X0); wall C, off to the side, is in view for 17
// iterations (44–60) only. It joins the current group at 48 with 5 readings, and its comparison
// with B can never reach min_interval (20).
struct ShortWall {
  std::vector<test::Wall> walls = {{{120, 2}, {-10, 2}}, {{-10, -2}, {120, -2}}, {{30, -3}, {31, -3}}};
  test::PlaneRun world;
  ShortWall() {
    test::PathBuilder path(PlanarPose::from(0, 0, 0));
    path.move(100, 0.5);
    world = test::run_path(walls, path.poses(), {.near = 1, .far = 8, .half_width = 3.5});
  }
};

// Which groups the RltPlane of wall `wall` ends up in, and whether it is on the map.
struct Fate {
  std::vector<XPointId> groups;
  bool mapped = false;
  PlaneId plane = kNone;
};

Fate fate_of(const RltXPointsS& slam, const test::PlaneRun& world, int wall) {
  Fate f;
  // The RltPlane created from the wall's first observation: planes are in creation order and
  // the fixture's walls are seen whole, one RltPlane each.
  for (PlaneId p = 0; p < static_cast<PlaneId>(slam.planes().size()); ++p) {
    const PlaneObject& first = slam.planes()[p].first_observation();
    const int t = first.iteration;
    const auto& ids = world.wall_ids[static_cast<std::size_t>(t)];
    for (std::size_t i = 0; i < ids.size(); ++i)
      if (ids[i] == wall && world.frames[static_cast<std::size_t>(t)].planes[i].a == first.a) f.plane = p;
  }
  if (f.plane == kNone) return f;
  for (const RltXPointRef& r : slam.planes()[f.plane].refs()) f.groups.push_back(r.xpoint);
  f.mapped = slam.map()[f.plane].mapped;
  return f;
}

TEST(RltXPointsS, ShortIntervalPlaneGetsANewGroupThenLeavesTheMap) {
  const ShortWall scene;
  RelativePlaneOptions options;
  {  // Without Rules 31–34 C stays in X0, compared with B over 17 iterations.
    RltXPointsS slam(options, scene.world.world_T_robot.front());
    for (const PlaneFrame& f : scene.world.frames) slam.step(f);
    const Fate c = fate_of(slam, scene.world, 2);
    ASSERT_NE(c.plane, kNone);
    EXPECT_EQ(c.groups, std::vector<XPointId>{0});
    EXPECT_TRUE(c.mapped);
    EXPECT_EQ(slam.planes()[c.plane].ref(0)->join_iteration, 48);
  }
  options.rules.interval_check = true;
  RltXPointsS slam(options, scene.world.world_T_robot.front());
  std::vector<RollBackEvent> events;
  for (const PlaneFrame& f : scene.world.frames) {
    const RelativePlaneStep s = slam.step(f);
    events.insert(events.end(), s.roll_backs.begin(), s.roll_backs.end());
  }
  // 108 = 48 + confirm_after: level 1, not in X0 → the replay starts X1 for C (nothing adjacent);
  // 108 again: C fails in the group it started → level 3 at once (thesis 4.5) → off the map.
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].iteration_requested, 108);
  EXPECT_EQ(events[0].target_iteration, 48);
  EXPECT_EQ(events[0].level, 1);
  EXPECT_EQ(events[0].xpoint, 0);
  // 48..108, from the checkpoint before 48 (one every checkpoint_period).
  EXPECT_GE(events[0].replayed_iterations, 61);
  EXPECT_LE(events[0].replayed_iterations, 61 + options.rollback.checkpoint_period);
  EXPECT_EQ(events[1].level, 3);
  EXPECT_EQ(events[1].xpoint, 1);
  ASSERT_EQ(slam.hints().all().size(), 2u);
  const Fate c = fate_of(slam, scene.world, 2);
  ASSERT_NE(c.plane, kNone);
  EXPECT_TRUE(c.groups.empty());
  EXPECT_FALSE(c.mapped);
  EXPECT_EQ(slam.xpoints().size(), 1u);  // X1 was made in a replay that no longer exists
  const Fate a = fate_of(slam, scene.world, 0), b = fate_of(slam, scene.world, 1);
  EXPECT_TRUE(a.mapped);
  EXPECT_TRUE(b.mapped);
}

// Interval checks on (so the history is kept) that every membership passes at once.
RelativePlaneOptions checks_that_pass() {
  RelativePlaneOptions o;
  o.rules.interval_check = true;
  o.rollback.min_interval = 1;
  return o;
}

// Each level sent by hand (Rule 34's general form) at C's join iteration: NotInX(X0) puts C in a
// new group of its own, NoExistingX too (there is no other group to try), NotOnMap in none.
TEST(RltXPointsS, EachHintLevelDoesWhatItSaysOnReplay) {
  const ShortWall scene;
  for (const HintLevel level : {HintLevel::NotInX, HintLevel::NoExistingX, HintLevel::NotOnMap}) {
    RltXPointsS slam(checks_that_pass(), scene.world.world_T_robot.front());
    PlaneIdentity c_identity;
    for (std::size_t t = 0; t < scene.world.frames.size(); ++t) {
      if (t == 70) {
        const Fate c = fate_of(slam, scene.world, 2);
        ASSERT_EQ(c.groups, std::vector<XPointId>{0});
        c_identity = slam.identity(c.plane);
        slam.send_hint({level, c_identity, 48, 0});
      }
      slam.step(scene.world.frames[t]);
    }
    SCOPED_TRACE(::testing::Message() << "level " << static_cast<int>(level));
    const Fate c = fate_of(slam, scene.world, 2);
    ASSERT_NE(c.plane, kNone);
    EXPECT_TRUE(slam.identity(c.plane) == c_identity);
    if (level == HintLevel::NotOnMap) {
      EXPECT_TRUE(c.groups.empty());
      EXPECT_FALSE(c.mapped);
    } else {
      EXPECT_EQ(c.groups, std::vector<XPointId>{1});  // its own, linked to X0 by A and B
      EXPECT_EQ(slam.xpoints()[1].planes().back(), c.plane);
      EXPECT_TRUE(c.mapped);
    }
  }
}

// NotInX names one group: a hint against a group C never joins changes nothing in the replay.
TEST(RltXPointsS, HintForAnotherGroupChangesNothing) {
  const ShortWall scene;
  const Outcome plain = run(scene.world, checks_that_pass());
  RltXPointsS slam(checks_that_pass(), scene.world.world_T_robot.front());
  std::vector<StepCopy> steps;
  for (std::size_t t = 0; t < scene.world.frames.size(); ++t) {
    if (t == 70) slam.send_hint({HintLevel::NotInX, slam.identity(fate_of(slam, scene.world, 2).plane), 48, 5});
    const RelativePlaneStep s = slam.step(scene.world.frames[t]);
    steps.push_back(copy_of(s));
    if (t == 70) {
      EXPECT_EQ(s.roll_back.rollbacks, 1);
    }
  }
  expect_same_runs(plain.steps, steps);
}

// Determinism with the interval checks on: two runs of the same input are the same, with the
// same roll-backs and hints.
TEST(RltXPointsS, IntervalCheckRunsAreDeterministic) {
  const ShortWall scene;
  RelativePlaneOptions options = with_key_points();
  options.rules.interval_check = true;
  for (const test::PlaneRun& world : {scene.world, hallway_there_and_back()}) {
    const Outcome a = run(world, options), b = run(world, options);
    expect_same_runs(a.steps, b.steps);
    EXPECT_EQ(a.counts.rollbacks, b.counts.rollbacks);
    EXPECT_EQ(a.counts.hints, b.counts.hints);
    EXPECT_EQ(a.log.size(), b.log.size());
  }
}

// max_nesting bounds the roll-backs of one step: with 1, a roll-back asked for during a replay is
// refused and counted, and the step still ends at the current iteration.
TEST(RltXPointsS, NestedRollBacksBeyondMaxNestingAreRefused) {
  const ShortWall scene;
  RelativePlaneOptions options;
  options.rules.interval_check = true;
  options.rollback.max_nesting = 1;
  RltXPointsS slam(options, scene.world.world_T_robot.front());
  RollBackCounts counts;
  for (std::size_t t = 0; t < scene.world.frames.size(); ++t) {
    // At 108 C's check rolls back to 48; asking for another one in the same step nests it.
    if (t == 108) slam.request_roll_back(100);
    const RelativePlaneStep s = slam.step(scene.world.frames[t]);
    EXPECT_EQ(s.iteration, static_cast<int>(t));
    counts.rollbacks += s.roll_back.rollbacks;
    counts.refused += s.roll_back.refused;
  }
  // The earliest target is served (48), the one at 100 merged into it; C's second check at 108
  // of the replay is nested and refused.
  EXPECT_EQ(counts.rollbacks, 1);
  EXPECT_GE(counts.refused, 1);
  for (const RollBackEvent& e : slam.roll_back_log())
    EXPECT_TRUE(e.outcome == RollBackOutcome::Replayed || e.outcome == RollBackOutcome::Nesting);
}

}  // namespace
}  // namespace relslam::plane
