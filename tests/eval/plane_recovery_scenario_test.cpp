// Relative Plane's adaptive preset when the pose is lost (pose_integrity.hpp, relocalisation): the
// planes in view are matched against the map and the pose resumes once two mapped non-parallel
// planes are in view, with no wrong pose called valid. The loss is forced: a planted gap of
// frames (the sensor reports nothing while the robot moves on) on generated maps
// (docs/generated-maps.md).
#include "test_support.hpp"

#include "relslam/eval/metrics/plane_map_error.hpp"
#include "relslam/eval/sources/planar_simulation_source.hpp"
#include "relslam/plane/rlt_xpoints_s.hpp"
#include "relslam/sim/map_generator.hpp"
#include "relslam/sim/planar_simulator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace relslam::eval {
namespace {

constexpr double kWrong = 0.5;  // a valid pose further off is wrong-but-valid (the recorder's bound)

// A turn in place of about 180 degrees (a dead end's), iterations [first, last].
struct Turn {
  int first = 0;
  int last = 0;
};

std::vector<Turn> dead_end_turns(const sim::PlanarSimulator& simulator) {
  std::vector<Turn> turns;
  double turned = 0;
  for (int k = 1; k < simulator.iterations(); ++k) {
    const PlanarPose a = simulator.path().world_T_robot(k - 1), b = simulator.path().world_T_robot(k);
    const bool turning = (b.translation - a.translation).norm() < 1e-9 && std::abs(wrap_angle(b.heading - a.heading)) > 1e-9;
    if (!turning) continue;
    if (turns.empty() || turns.back().last != k - 1) {
      if (!turns.empty() && std::abs(turned) < 3.0) turns.pop_back();  // not a half turn
      turns.push_back({k, k});
      turned = 0;
    }
    turns.back().last = k;
    turned += wrap_angle(b.heading - a.heading);
  }
  if (!turns.empty() && std::abs(turned) < 3.0) turns.pop_back();
  return turns;
}

struct GapRun {
  int iterations = 0;
  int valid = 0;
  int wrong_valid = 0;
  double max_valid_error = 0;
  std::optional<int> first_valid_after_gap;  // iterations after the gap ends
  int valid_after_gap = 0;
  int wrong_valid_after_gap = 0;  // within 150 iterations after it
  std::vector<bool> valid_at;
  std::vector<bool> wrong_at;
};

// The map's path through the adaptive preset with the frames [gap_from, gap_from + gap) empty;
// with `view` the sensor's field of view is known, as a scenario gives it (evidence against a
// place, real ends), without it neither.
GapRun run_with_gap(const sim::PlanarMap& map, bool recovery, int gap_from, int gap, bool view = true) {
  const sim::PlanarSimulator simulator(map, 1);
  plane::RelativePlaneOptions options = plane::preset_options(plane::Preset::Adaptive);
  options.integrity.recovery = recovery;
  if (view) options.integrity.field_of_view = *sensor_field_of_view(map.sensor);
  plane::RltXPointsS slam(options, simulator.path().world_T_robot(0));
  GapRun out;
  for (int k = 0; k < simulator.iterations(); ++k) {
    sim::PlaneSimFrame frame = simulator.frame(k);
    const bool dark = k >= gap_from && k < gap_from + gap;
    if (dark) frame.observation.planes.clear();
    const plane::RelativePlaneStep step = slam.step(frame.observation);
    ++out.iterations;
    out.valid_at.push_back(step.pose_valid);
    out.wrong_at.push_back(false);
    if (!step.pose_valid) continue;
    const double error = planar_pose_error(step.world_T_robot, frame.truth.world_T_robot).position;
    ++out.valid;
    out.wrong_valid += error > kWrong;
    out.wrong_at.back() = error > kWrong;
    if (k >= gap_from + gap && k < gap_from + gap + 150) out.wrong_valid_after_gap += error > kWrong;
    out.max_valid_error = std::max(out.max_valid_error, error);
    if (k >= gap_from + gap) {
      ++out.valid_after_gap;
      if (!out.first_valid_after_gap) out.first_valid_after_gap = k - (gap_from + gap);
    }
  }
  return out;
}

std::string describe(const GapRun& r) {
  return std::to_string(r.valid) + " of " + std::to_string(r.iterations) + " valid, " +
         std::to_string(r.wrong_valid) + " wrong-valid, largest error " + std::to_string(r.max_valid_error) +
         ", first valid " + (r.first_valid_after_gap ? std::to_string(*r.first_valid_after_gap) : "never") +
         " iterations after the gap, " + std::to_string(r.valid_after_gap) + " valid after it";
}

sim::PlanarMap generated(sim::MapFamily family, std::uint64_t seed) {
  sim::PlanarMap map = sim::generate_map({.family = family, .seed = seed});
  map.sensor.noise = sim::PlaneNoiseOptions::none();
  return map;
}

// A planted gap of 20 frames (the sensor reports nothing while the robot moves on) in a generated
// corridor, noise-free: the local registration (Rule 1) has lost every plane and the old pose
// no longer places them (Rule 11), so without relocalisation the pose never comes back; with it
// the planes in view are matched against the map and the pose resumes at once, and the algorithm
// with it (Rule 11 from the recovered pose).
TEST(PlaneRecovery, ResumesAfterAPlantedGap) {
  struct Case {
    sim::MapFamily family;
    int gap_from;
    int within;  // the first valid pose at most this many iterations after the gap
  };
  // Measured (the field of view known, real ends on): the corridor resumes 2 iterations after the
  // gap (982 valid after it; relocalised at +1, reported once the lines confirm it), the mirrored
  // corridor 50 (530 valid after it); without relocalisation neither has a valid pose after it.
  for (const Case c : {Case{sim::MapFamily::Corridor, 300, 5}, Case{sim::MapFamily::MirroredCorridor, 900, 60}}) {
    SCOPED_TRACE(std::string(to_string(c.family)));
    const sim::PlanarMap map = generated(c.family, 1);
    const GapRun off = run_with_gap(map, false, c.gap_from, 20);
    const GapRun on = run_with_gap(map, true, c.gap_from, 20);
    std::cout << to_string(c.family) << " off: " << describe(off) << "\n" << to_string(c.family) << " on: " << describe(on)
              << "\n";
    EXPECT_EQ(off.valid_after_gap, 0) << "the loss relocalisation mends";
    ASSERT_TRUE(on.first_valid_after_gap.has_value());
    EXPECT_LE(*on.first_valid_after_gap, c.within);
    EXPECT_GE(on.valid_after_gap, 250);
    EXPECT_EQ(on.wrong_valid_after_gap, 0);
  }
}

// The dead end's 180-degree turn, large frustum, noise-free: the pose is valid again within two
// iterations after every turn and through the next 150 (the runs lost it for the rest of
// the path), with no wrong pose called valid around the turn. Generated corridors, map seeds 1-3.
TEST(PlaneRecovery, DeadEndTurnKeepsThePoseWithTheLargeFrustum) {
  for (const std::uint64_t seed : {1, 2, 3}) {
    sim::PlanarMap map = generated(sim::MapFamily::Corridor, seed);
    map.sensor.frustum = sim::ViewingFrustum::large();
    const sim::PlanarSimulator simulator(map, 1);
    const GapRun r = run_with_gap(map, false, 0, 0);  // as a scenario runs it
    for (const Turn& t : dead_end_turns(simulator)) {
      if (t.last + 150 >= r.iterations) continue;  // the path's last turn ends it
      SCOPED_TRACE("map seed " + std::to_string(seed) + ", turn ending at " + std::to_string(t.last));
      int first = -1, valid = 0, wrong = 0;
      for (int k = t.first; k <= t.last + 150; ++k) {
        wrong += r.wrong_at[k];
        if (k <= t.last) continue;
        valid += r.valid_at[k];
        if (r.valid_at[k] && first < 0) first = k - t.last;
      }
      std::cout << "map seed " << seed << ", turn " << t.first << "-" << t.last << ": first valid +" << first << ", "
                << valid << " of 150 after, " << wrong << " wrong-valid\n";
      EXPECT_GE(first, 1);
      EXPECT_LE(first, 2);
      EXPECT_GE(valid, 145);
      EXPECT_EQ(wrong, 0);
    }
  }
}

// The first valid pose after each dead end's 180-degree turn (iterations after it ends, -1:
// none within 150) and the wrong valid poses from the turn's start to 150 after it.
struct TurnOutcome {
  int first = -1;
  int wrong = 0;
};

std::vector<TurnOutcome> turn_outcomes(const sim::PlanarMap& map, bool view) {
  const sim::PlanarSimulator simulator(map, 1);
  const GapRun r = run_with_gap(map, true, 0, 0, view);
  std::vector<TurnOutcome> out;
  for (const Turn& t : dead_end_turns(simulator)) {
    if (t.last + 150 >= r.iterations) continue;  // the path's last turn ends it
    TurnOutcome o;
    for (int k = t.first; k <= t.last + 150; ++k) {
      o.wrong += r.wrong_at[k];
      if (k > t.last && r.valid_at[k] && o.first < 0) o.first = k - t.last;
    }
    out.push_back(o);
  }
  return out;
}

// The dead end's 180-degree turn with the small frustum, noise-free: looking back down the
// corridor it sees only the two parallel sides, which fix no position along them (thesis 4.2.5),
// so the pose stayed lost 51 iterations after the first turn of map seed 1 (and 51-130 or for
// the rest of the path after others). With the field of view known, the pieces' real ends in
// view fix it on the map's ends (end_fix.hpp): valid again within kWithin iterations, with no
// wrong pose called valid from the turn's start to 150 iterations after it. Not yet on every
// turn: map seeds 2 and 3 and the second turn of seed 1 (docs/generated-maps.md).
TEST(PlaneRecovery, DeadEndTurnComesBackWithTheSmallFrustum) {
  constexpr int kWithin = 5;
  const sim::PlanarMap map = generated(sim::MapFamily::Corridor, 1);
  const std::vector<TurnOutcome> with = turn_outcomes(map, true), without = turn_outcomes(map, false);
  ASSERT_FALSE(with.empty());
  ASSERT_EQ(with.size(), without.size());
  std::cout << "first turn: first valid +" << with[0].first << " (without the field of view +" << without[0].first
            << "), wrong-valid " << with[0].wrong << " (without " << without[0].wrong << ")\n";
  EXPECT_GE(with[0].first, 1);
  EXPECT_LE(with[0].first, kWithin);
  EXPECT_EQ(with[0].wrong, 0);
  EXPECT_TRUE(without[0].first < 0 || without[0].first > kWithin) << "the turn came back without the change too";
}

}  // namespace
}  // namespace relslam::eval
