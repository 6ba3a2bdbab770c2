// The Relative Plane algorithm (thesis Chapter 4, part 1: Rules 1–12) on the simulator's planar
// maps (scenarios/maps/*.json), scored against the truth as eval scores it:
// E03 (Map A with noise), E04 (Map B), E05 (Map C's edge-on wall) through the real sensor.
#include "test_support.hpp"

#include "relslam/eval/io/planar_map_file.hpp"
#include "relslam/eval/metrics/plane_map_error.hpp"
#include "relslam/plane/rlt_xpoints_s.hpp"
#include "relslam/sim/planar_simulator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <numbers>
#include <set>
#include <vector>

namespace relslam::eval {
namespace {

using plane::RelativePlaneOptions;
using plane::RelativePlaneStep;
using plane::RltXPointsS;

// noise-free runs keep map and pose within 1e-6 wherever the pose is valid.
constexpr double kNoiseFree = 1e-6;

sim::PlanarMap map_file(const std::string& name) {
  return read_planar_map(test::source_path("scenarios/maps/" + name));
}

sim::PlanarMap noise_free(sim::PlanarMap map) {
  map.sensor.noise = sim::PlaneNoiseOptions::none();
  return map;
}

struct IterationScore {
  bool pose_valid = false;
  PlanarPoseError pose;
  PlaneMapError map;     // e_ends against the majority wall, key point to key point
  double map_faced = 0;  // the sum of e_ends with a plane facing away scored against the wall turned round
  int rlt_planes = 0;    // RltPlanes so far
  int on_map = 0;        // RltPlanes on the map
  bool motion_model = false;  // a motion model carried the pose (Rules 23–27)
};

struct SimRun {
  std::vector<IterationScore> iterations;
  std::map<int, std::set<int>> planes_of_wall;  // true wall -> the RltPlanes it is the majority wall of
  std::map<int, int> mapped_of_wall;            // true wall -> how many of those are on the final map
  int rlt_planes = 0;
  int mixed_faces = 0;  // RltPlanes given observations of both faces of their wall (what Rule 10 forbids)
  int global_matches = 0;
  std::map<int, PlaneError> final_error;  // RltPlane on the final map -> its error against its wall
  std::map<int, int> final_wall;          // ... and that wall
  std::map<int, int> motion_models_by;    // iteration -> motion models started so far
  std::map<int, double> longest_seen;     // RltPlane -> its longest observation (Rule 17: its largest size seen)
  std::map<int, std::array<bool, 2>> wall_ends_seen;  // true wall -> each real end ever in an observation
};

// The walls whose two real ends were not both ever in view: no map can know their length.
std::set<int> walls_with_an_end_never_seen(const SimRun& run) {
  std::set<int> out;
  for (const auto& [wall, ends] : run.wall_ends_seen)
    if (!ends[0] || !ends[1]) out.insert(wall);
  return out;
}

// The walls with no plane on the final map at full length.
std::set<int> walls_short_on_the_map(const SimRun& run, double tolerance) {
  std::set<int> whole, out;
  for (const auto& [p, e] : run.final_error)
    if (e.length_ratio > 1 - tolerance) whole.insert(run.final_wall.at(p));
  for (const auto& [p, wall] : run.final_wall)
    if (!whole.contains(wall)) out.insert(wall);
  return out;
}

// e_ends of `mapped` against `wall`, or against the wall seen from behind (ends swapped) when the
// mapped plane faces the other way: with back-face culling off a wall's back is a plane of its
// own (Rule 10), rightly placed but with its key points the other way round.
double faced_error(const PlaneObject& mapped, const PlaneObject& wall) {
  return plane_error(mapped, mapped.normal().dot(wall.normal()) >= 0 ? wall : PlaneObject{wall.b, wall.a}).ends;
}

// Runs the map's simulator (seeded) into RltXPointsS and scores every iteration.
SimRun run_map(const sim::PlanarMap& map, std::uint64_t seed, const RelativePlaneOptions& options = {}) {
  const sim::PlanarSimulator simulator(map, seed);
  std::vector<PlaneObject> walls(map.world.walls.size());
  for (const sim::Wall& w : map.world.walls) walls.at(w.id) = PlaneObject{w.a, w.b};
  RltXPointsS slam(options, simulator.path().world_T_robot(0));
  WallVotes votes;
  std::map<int, std::set<bool>> faces;  // RltPlane -> the faces it was given (true: the front)
  SimRun out;
  std::vector<std::pair<int, PlaneObject>> mapped;
  for (int k = 0; k < simulator.iterations(); ++k) {
    const sim::PlaneSimFrame frame = simulator.frame(k);
    const RelativePlaneStep step = slam.step(frame.observation);
    for (std::size_t i = 0; i < step.assignment.size(); ++i) {
      const int wall = frame.truth.planes[i].wall_id;
      votes.add(step.assignment[i], wall);
      std::array<bool, 2>& ends = out.wall_ends_seen[wall];
      ends[0] = ends[0] || frame.truth.planes[i].a_is_wall_end;
      ends[1] = ends[1] || frame.truth.planes[i].b_is_wall_end;
      double& longest = out.longest_seen[step.assignment[i]];
      longest = std::max(longest, frame.observation.planes[i].length());
      const PlaneObject seen = frame.observation.planes[i].transformed(frame.truth.world_T_robot);
      faces[step.assignment[i]].insert(seen.normal().dot(walls.at(wall).normal()) > 0);
    }
    out.global_matches += step.global_matches;
    IterationScore score;
    score.pose_valid = step.pose_valid;
    score.motion_model = step.motion_model != nullptr;
    if (step.pose_valid) score.pose = planar_pose_error(step.world_T_robot, frame.truth.world_T_robot);
    mapped.clear();
    for (std::size_t p = 0; p < step.map.size(); ++p) {
      if (!step.map[p].mapped) continue;
      mapped.emplace_back(static_cast<int>(p), step.map[p].plane);
      score.map_faced += faced_error(step.map[p].plane, walls.at(votes.wall_of(static_cast<int>(p))));
    }
    score.map = plane_map_error(mapped, votes, walls);
    score.on_map = static_cast<int>(mapped.size());
    score.rlt_planes = static_cast<int>(slam.planes().size());
    out.iterations.push_back(score);
    out.motion_models_by[k] = static_cast<int>(slam.motion_models().size());
  }
  out.rlt_planes = static_cast<int>(slam.planes().size());
  for (int p = 0; p < out.rlt_planes; ++p) {
    out.planes_of_wall[votes.wall_of(p)].insert(p);
    out.mapped_of_wall[votes.wall_of(p)] += slam.map()[p].mapped;
  }
  for (const auto& [p, seen] : faces) out.mixed_faces += seen.size() > 1;
  for (int p = 0; p < out.rlt_planes; ++p) {
    if (!slam.map()[p].mapped || votes.wall_of(p) < 0) continue;
    out.final_wall[p] = votes.wall_of(p);
    out.final_error[p] = plane_error(slam.map()[p].plane, walls.at(votes.wall_of(p)));
  }
  return out;
}

struct Worst {
  int valid = 0;
  double position = 0, heading = 0, map = 0;
};

Worst worst_of(const SimRun& run, int from = 0, int to = -1) {
  Worst w;
  if (to < 0) to = static_cast<int>(run.iterations.size());
  for (int k = from; k < to; ++k) {
    const IterationScore& s = run.iterations[k];
    if (!s.pose_valid) continue;
    ++w.valid;
    w.position = std::max(w.position, s.pose.position);
    w.heading = std::max(w.heading, s.pose.heading_rad);
    w.map = std::max(w.map, s.map.sum);
  }
  return w;
}

// Each true wall is represented by exactly one RltPlane (and every wall was seen).
void expect_one_plane_per_wall(const SimRun& run, const sim::PlanarMap& map) {
  EXPECT_EQ(run.planes_of_wall.size(), map.world.walls.size());
  for (const auto& [wall, planes] : run.planes_of_wall) EXPECT_EQ(planes.size(), 1u) << "wall " << wall;
  EXPECT_EQ(run.rlt_planes, static_cast<int>(map.world.walls.size()));
}

// E03 (thesis 4.3.1, Figs 64, 70; Rules 1–5): Map A, always visible, ten loops, Gaussian noise
// (σ_p = 0.01, σ_r = 0.3°). No drift: the map error (sum of e_ends over the four
// walls) averaged over the last loop is within 10 % of the first loop's — measured: seed 1
// 0.0373 → 0.0358, seed 2 0.0684 → 0.0680, seed 3 0.0507 → 0.0474 — and the pose error stays
// at single-iteration noise level (measured at most 0.06 and 0.011 rad) in every loop.
TEST(PlaneScenario, MapAFourPlanesWithNoiseDoesNotDriftOverTenLoops) {
  const sim::PlanarMap map = map_file("a_four_planes.json");
  ASSERT_EQ(map.sensor.noise.model, sim::PlaneNoiseModel::Gaussian);
  for (std::uint64_t seed : {1, 2, 3}) {
    const SimRun run = run_map(map, seed);
    const int loop = static_cast<int>(run.iterations.size() - 1) / 10;  // iteration 0 is the start pose
    ASSERT_EQ(loop, 560);
    std::vector<double> loop_mean;
    for (int l = 0; l < 10; ++l) {
      double sum = 0;
      int n = 0;
      for (int k = 1 + l * loop; k <= (l + 1) * loop; ++k)
        if (run.iterations[k].pose_valid) sum += run.iterations[k].map.sum, ++n;
      ASSERT_GT(n, loop - 10) << "seed " << seed << " loop " << l;
      loop_mean.push_back(sum / n);
      const Worst w = worst_of(run, 1 + l * loop, (l + 1) * loop + 1);
      EXPECT_LT(w.position, 0.1) << "seed " << seed << " loop " << l;   // 10 σ_p
      EXPECT_LT(w.heading, 0.025) << "seed " << seed << " loop " << l;  // about 5 σ_r
    }
    EXPECT_GT(loop_mean.front(), 0.005) << "seed " << seed;  // noise reaches the map: the ratio means something
    EXPECT_LE(loop_mean.back(), 1.1 * loop_mean.front()) << "seed " << seed;
    EXPECT_EQ(run.rlt_planes, 4);
  }
}

// E04 (thesis 4.3.2, Fig. 71; Rules 6–9): Map B's scripted windows without noise, through the
// simulator: exact at every iteration with a valid pose (measured 7e-15 pose, 6e-14 map).
TEST(PlaneScenario, MapBHallwayNoiseFreeIsExactAtEveryValidIteration) {
  const sim::PlanarMap map = noise_free(map_file("b_hallway_unit.json"));
  const SimRun run = run_map(map, 1);
  const Worst w = worst_of(run);
  EXPECT_GT(w.valid, 750);  // of 761
  EXPECT_LT(w.position, kNoiseFree);
  EXPECT_LT(w.heading, kNoiseFree);
  EXPECT_LT(w.map, kNoiseFree);
  expect_one_plane_per_wall(run, map);
}

// Map C with its own sensor (small frustum, full-size planes, back-face culling on) without
// noise: full-size planes need no key points (part 2), so the run is exact (measured 7e-15
// pose, 6e-14 map), and on the return leg every wall is taken back by Rule 11: no RltPlane is
// made after the turn, one per true wall.
TEST(PlaneScenario, MapCHallwayBackNoiseFreeIsExactAndTheReturnLegMakesNoDuplicates) {
  const sim::PlanarMap map = noise_free(map_file("c_hallway_back.json"));
  ASSERT_EQ(map.sensor.mode, sim::PlaneVisibility::FullSize);
  const sim::PlanarSimulator simulator(map, 1);
  const int turn_end = simulator.path().operation_ends().at(1);  // MOVE 36, TURN 180, MOVE 36
  const SimRun run = run_map(map, 1);
  const Worst w = worst_of(run);
  EXPECT_GT(w.valid, 1450);  // of 1561
  EXPECT_LT(w.position, kNoiseFree);
  EXPECT_LT(w.heading, kNoiseFree);
  EXPECT_LT(w.map, kNoiseFree);
  expect_one_plane_per_wall(run, map);
  EXPECT_EQ(run.iterations[turn_end].rlt_planes, run.rlt_planes);
  EXPECT_GT(run.global_matches, 0);
}

// E05 (thesis 4.3.2, Fig. 72; Rule 10): Map C with noise; the robot turns on the line of the
// side corridor's x = 36 wall (wall 18), which it sees edge-on while its heading passes 60°–120°.
// (a) Back-face culling off, Rule 10 off: the edge-on wall's noisy observations flip between
// its faces and still match one RltPlane, whose comparisons then say two robot poses: the pose
// breaks from the iteration the wall comes into view, and the walls seen again become new
// planes. (b) Culling off, Rule 10 on: each face is an RltPlane of its own, no RltPlane mixes
// faces, and pose and map (each face scored against the wall turned its way) stay at noise
// level as in (c), culling on: one RltPlane per wall. Measured, seeds 1–3: (a) worst pose
// 5.1/9.5/9.7 units, heading off by π (π/2 with seed 4); 21/33/33 RltPlanes for 19 walls.
// (b) worst pose 0.067/0.13/0.14, final map 0.52/1.37/1.54. (c) 0.066/0.135/0.139,
// 0.45/1.17/1.31; 19 RltPlanes.
TEST(PlaneScenario, MapCEdgeOnWallBreaksThePoseOnlyWithoutRule10) {
  const sim::PlanarMap shipped = map_file("c_hallway_back.json");
  ASSERT_EQ(shipped.sensor.noise.model, sim::PlaneNoiseModel::Gaussian);
  sim::PlanarMap both_sides = shipped;
  both_sides.sensor.backface_cull = false;
  RelativePlaneOptions no_rule10;
  no_rule10.rules.normal_direction = false;
  const sim::PlanarSimulator simulator(shipped, 1);
  const int move_end = simulator.path().operation_ends().at(0), turn_end = simulator.path().operation_ends().at(1);
  constexpr int kEdgeOnWall = 18;
  for (std::uint64_t seed : {1, 2, 3}) {
    const SimRun a = run_map(both_sides, seed, no_rule10);
    const SimRun b = run_map(both_sides, seed);
    const SimRun c = run_map(shipped, seed);
    // (a) Fine until the turn; broken once the edge-on wall is in view (heading ≥ 60°).
    EXPECT_LT(worst_of(a, 0, move_end + 1).position, 0.25) << "seed " << seed;
    const int in_view = move_end + 40;  // 60° at 1.5° an iteration
    EXPECT_LT(worst_of(a, 0, in_view - 1).position, 0.25) << "seed " << seed;
    const Worst a_turn = worst_of(a, in_view - 1, turn_end + 1);
    EXPECT_GT(std::max(a_turn.position, a_turn.heading), 1.0) << "seed " << seed;
    EXPECT_GT(worst_of(a).heading, 1.0) << "seed " << seed;  // a pose turned by π/2 or π
    EXPECT_GE(a.mixed_faces, 1) << "seed " << seed;
    EXPECT_EQ(a.planes_of_wall.at(kEdgeOnWall).size(), 1u) << "seed " << seed;  // both faces in one RltPlane
    EXPECT_GT(a.rlt_planes, static_cast<int>(shipped.world.walls.size()) + 1) << "seed " << seed;
    // (b) and (c): the pose stays at noise level throughout; no RltPlane mixes faces.
    for (const SimRun* run : {&b, &c}) {
      const Worst w = worst_of(*run);
      EXPECT_GT(w.valid, 1450) << "seed " << seed;
      EXPECT_LT(w.position, 0.25) << "seed " << seed;
      EXPECT_LT(w.heading, 0.03) << "seed " << seed;
      EXPECT_EQ(run->mixed_faces, 0) << "seed " << seed;
      EXPECT_LT(run->iterations.back().map_faced, 2.0) << "seed " << seed;
    }
    // (b): the two-sided corridor walls (17, 18) have a mapped RltPlane per face; every other
    // wall one RltPlane. A face seen only now and then (the edge-on wall's back, flickering in
    // and out with the noise) may leave an RltPlane that never reaches min_readings before a gap
    // longer than Rule 1's: it is dropped from the unassigned list, never mapped (seeds 1, 5).
    for (const auto& [wall, planes] : b.planes_of_wall) {
      if (wall == 17 || wall == kEdgeOnWall) {
        EXPECT_EQ(b.mapped_of_wall.at(wall), 2) << "seed " << seed << " wall " << wall;
        EXPECT_LE(planes.size(), 3u) << "seed " << seed << " wall " << wall;
      } else {
        EXPECT_EQ(planes.size(), 1u) << "seed " << seed << " wall " << wall;
      }
    }
    // (c): one RltPlane per wall, none made on the way back.
    expect_one_plane_per_wall(c, shipped);
    EXPECT_EQ(c.iterations[turn_end].rlt_planes, c.rlt_planes) << "seed " << seed;
  }
}

// Map D (thesis Figs 67, 73–82) without noise, parts 2 and 3's motion model on: walls cut by
// the frustum are compared by their key points (Rules 13–15, 18, 19), chained with size
// correction (Rule 28), placed at their largest size from their key point (Rule 17, A47) and
// grown to that size for the pose (Rule 16); at a corner, where one partial wall is in view
//, the motion model (Rules 23–27) carries the pose. Noise-free the growth phases
// are split without a moving average (window 1: Fig 105's lag puts samples of the next phase
// into a piece) and "the same size" is exact (τ_len 1e-9: an end cut by less than τ_len would
// otherwise be taken for the whole plane).
RelativePlaneOptions noise_free_key_points() {
  RelativePlaneOptions options;
  options.key_points = true;
  options.growth_phase.window = 1;
  options.same_length = 1e-9;
  options.rigid_sigma = 1e-6;  // noise-free: a comparison is rigid or wrong
  return options;
}

// e_ends of a plane mapped at its largest size seen: the key-point end exact, the other short by
// the part never seen, no angle or offset error, never longer than the wall.
void expect_one_end_exact(const SimRun& run, const sim::PlanarMap& map) {
  for (const auto& [p, e] : run.final_error) {
    const sim::Wall& wall = map.world.walls.at(run.final_wall.at(p));
    const double wall_length = (wall.b - wall.a).norm();
    EXPECT_LT(e.angle_rad, kNoiseFree) << "plane " << p;
    EXPECT_LT(e.perpendicular, kNoiseFree) << "plane " << p;
    EXPECT_LE(e.length_ratio, 1 + kNoiseFree) << "plane " << p;
    EXPECT_NEAR(e.ends, 0.5 * (1 - e.length_ratio) * wall_length, kNoiseFree) << "plane " << p;
  }
}

// The small frustum through the first two corners (iterations 0–700, two motion models):
// measured, the pose is exact (1e-14) at the 591 iterations it is valid; it is invalid for a few
// iterations after each corner and while only planes without a key point in the current piece
// are in view (438–490).
TEST(PlaneScenario, MapDSmallFrustumPassesTheFirstCornersExactlyWithTheMotionModel) {
  const sim::PlanarMap map = noise_free(map_file("d_office_loop.json"));
  ASSERT_EQ(map.sensor.mode, sim::PlaneVisibility::Frustum);
  const SimRun run = run_map(map, 1, noise_free_key_points());
  const Worst w = worst_of(run, 0, 700);
  EXPECT_GE(w.valid, 580);
  EXPECT_LT(w.position, kNoiseFree);
  EXPECT_LT(w.heading, kNoiseFree);
  EXPECT_GE(run.motion_models_by.at(700), 2);

  RelativePlaneOptions without = noise_free_key_points();
  without.rules.motion_model = false;  // the pose is lost at the first corner for good
  EXPECT_LT(worst_of(run_map(map, 1, without), 0, 700).valid, 300);
}

// The whole run (one loop and the partial second, 2501 iterations) through the small frustum.
// From 838 the collinear inner top pieces shrink and grow together (Fig 97): Rule 15 ties both
// diagonals, and the thesis's distance test (4.3.7.1) takes the one of the nearer key points,
// the real ends; without it no chain places the next plane and the pose is lost for good. Rule
// 36's reserves keep each plane's comparison from the interval where it was anchored on the
// same end as its canonical size (without them a plane never seen whole is chained across its
// two ends from 831 on: thesis 4.3.6's mixed anchor, off by the part never seen, 0.207).
// Two refinements make the run exact wherever the pose is valid (2475 of 2501 iterations):
// - rigid_sigma: at 718–720 (and 1318–1320, the same corner a loop later) the far corner of the
//   frustum sweeps wall 31 in during a turn, cut at both ends; the thesis compares it anyway
//   (Fig 105's case), and Rule 36 keeps that comparison for its size until 750 (up to 0.113);
// - regroup_unplaced: walls 2, 8 and 13 join their only group through their mirror across the
//   corridor, both cut by the frustum at the same place — a Rule 15 tie, no key point, off the
//   map for good; joining the next group gives them partners that are not their mirror.
TEST(PlaneScenario, MapDSmallFrustumWholeRunIsExactWhereverThePoseIsValid) {
  const sim::PlanarMap map = noise_free(map_file("d_office_loop.json"));
  const SimRun run = run_map(map, 1, noise_free_key_points());
  const Worst all = worst_of(run);
  EXPECT_GE(all.valid, 2470);
  EXPECT_LT(all.position, kNoiseFree);
  EXPECT_LT(all.heading, kNoiseFree);
  EXPECT_EQ(std::ranges::count_if(run.mapped_of_wall, [](const auto& w) { return w.second > 0; }), 36);
  // Key points right at every iteration; every plane exact at its largest size seen, and every
  // wall whose two real ends were ever in view on the map at full length (len_ratio 1 ± 1e-6:
  // every wall at its full length after the loop closes). The small frustum never shows
  // the far end of walls 20, 25, 32 and 35, not once in the run (at most 3.40 of 4 and 2.40 of 3
  // in view), so no map can know their length: they are mapped at their largest size seen (Rule
  // 17), their key-point end exact. Wall 3's first piece from the start stays on the map
  // beside the plane that maps it whole (the duplicate the thesis keeps, E15).
  expect_one_end_exact(run, map);
  EXPECT_EQ(walls_with_an_end_never_seen(run), (std::set<int>{20, 25, 32, 35}));
  EXPECT_EQ(walls_short_on_the_map(run, kNoiseFree), walls_with_an_end_never_seen(run));

  RelativePlaneOptions thesis_compare = noise_free_key_points();
  thesis_compare.rigid_sigma = 0;
  const Worst turn = worst_of(run_map(map, 1, thesis_compare), 723, 751);
  EXPECT_GT(turn.position, 0.03);

  RelativePlaneOptions stay = noise_free_key_points();
  stay.rules.regroup_unplaced = false;
  EXPECT_LE(std::ranges::count_if(run_map(map, 1, stay).mapped_of_wall, [](const auto& w) { return w.second > 0; }),
            33);

  // Without the distance test the tie is left to Rule 15: with regroup_unplaced the planes that
  // got no key point find it in the next group (measured 2352 valid, still exact); without either
  // no chain places the next plane and the pose is lost for good after 837.
  RelativePlaneOptions rule15_only = noise_free_key_points();
  rule15_only.key_point_ties.collinear_distance = false;
  const Worst regrouped = worst_of(run_map(map, 1, rule15_only));
  EXPECT_GE(regrouped.valid, 2300);
  EXPECT_LT(regrouped.position, kNoiseFree);
  rule15_only.rules.regroup_unplaced = false;
  EXPECT_LT(worst_of(run_map(map, 1, rule15_only), 838).valid, 10);
}

// The save system (Rules 35, 36; thesis 4.3.7.3, E19 / Figs 98–99 in small): with a store of 300
// observations per RltPlane the iterations two planes shared are overwritten long before the loop
// ends, their comparison can no longer be made, and without the save system their group loses
// them — the planes vanish from the map (measured: 31 of 36 walls left; 12 before Rule 11 came
// ahead of the unassigned list, when the loop closure also added duplicate groups). Either rule
// keeps them: Rule 35 restores the group's best complete result, Rule 36 each pair's best
// comparison (36 of 36 each, and with both on; the full store maps all 36).
TEST(PlaneScenario, MapDSmallStoreKeepsItsPlanesOnlyWithTheSaveSystem) {
  sim::PlanarMap map = noise_free(map_file("d_office_loop.json"));
  map.sensor.frustum = sim::ViewingFrustum::large();
  const auto run_with = [&](bool rule35, bool rule36) {
    RelativePlaneOptions options = noise_free_key_points();
    options.plane_capacity = 300;
    options.rules.save_snapshot = rule35;
    options.rules.save_reserve = rule36;
    return run_map(map, 1, options);
  };
  const auto walls_mapped = [](const SimRun& run) {
    return std::ranges::count_if(run.mapped_of_wall, [](const auto& wall) { return wall.second >= 1; });
  };
  EXPECT_LE(walls_mapped(run_with(false, false)), 31);
  EXPECT_EQ(walls_mapped(run_with(true, false)), 36);
  const SimRun rule36 = run_with(false, true);
  EXPECT_EQ(walls_mapped(rule36), 36);
  EXPECT_EQ(walls_mapped(run_with(true, true)), 36);
  // The reserves are exact comparisons: the pose stays exact wherever valid (measured: 2477 of
  // 2501 iterations, 5e-14, as with the full store).
  const Worst w = worst_of(rule36);
  EXPECT_GE(w.valid, 2450);
  EXPECT_LT(w.position, kNoiseFree);
  EXPECT_LT(w.heading, kNoiseFree);
}

// E19 at the thesis's store of 1200 observations (thesis 4.3.7.3, Figs 98–99): the thesis gives no
// speed, and at ours (0.05 a step) no wall is seen long enough for the store to overwrite what it
// shared with its neighbours before the loop brings them back together. At a quarter of it
// (planar.speed_scale 0.25, the E19 scenario) the mechanism of the test above comes back at the
// thesis's size: without Rules 35 and 36 planes vanish from the map (measured: it loses planes at 5
// iterations, 31 of 36 walls at the end), with both all 36 stay and the map never loses one.
TEST(PlaneScenario, MapDSlowRobotThesisStoreLosesPlanesWithoutTheSaveSystemOnly) {
  sim::PlanarMap map = noise_free(map_file("d_office_loop.json"));
  map.sensor.frustum = sim::ViewingFrustum::large();
  map.path.speed *= 0.25;
  map.path.turn_rate_rad *= 0.25;
  const auto run_with = [&](bool save) {
    RelativePlaneOptions options = noise_free_key_points();
    EXPECT_EQ(options.plane_capacity, 1200);
    options.rules.save_snapshot = save;
    options.rules.save_reserve = save;
    return run_map(map, 1, options);
  };
  const auto walls_mapped = [](const SimRun& run) {
    return std::ranges::count_if(run.mapped_of_wall, [](const auto& wall) { return wall.second >= 1; });
  };
  const auto planes_lost = [](const SimRun& run) {  // iterations whose map has fewer planes than the last
    int lost = 0;
    for (std::size_t k = 1; k < run.iterations.size(); ++k)
      lost += run.iterations[k].on_map < run.iterations[k - 1].on_map;
    return lost;
  };
  const SimRun unsaved = run_with(false);
  const SimRun saved = run_with(true);
  std::cout << "[ measured ] save system off: " << walls_mapped(unsaved) << " walls mapped, the map lost planes at "
            << planes_lost(unsaved) << " iterations; on: " << walls_mapped(saved) << ", " << planes_lost(saved) << '\n';
  EXPECT_LE(walls_mapped(unsaved), 33);
  EXPECT_GE(planes_lost(unsaved), 2);
  EXPECT_EQ(walls_mapped(saved), 36);
  EXPECT_EQ(planes_lost(saved), 0);
  // The pose is exact but at 2 iterations, 1469 and 1470 (0.0005 and 0.0019), the first two after
  // wall 7's near end leaves the view, cut by 0.005 and 0.017; at the normal speed the map's ends
  // leave the view in steps of 0.05 and no pose is off (the test above). Not traced further.
  int inexact = 0, valid = 0;
  double worst = 0;
  for (const IterationScore& s : saved.iterations) {
    if (!s.pose_valid) continue;
    ++valid;
    inexact += s.pose.position > kNoiseFree;
    worst = std::max(worst, s.pose.position);
  }
  EXPECT_GE(valid, 9900);  // measured 9977 of 10001
  EXPECT_LE(inexact, 4);
  EXPECT_LT(worst, 0.01);
}

// Rule 37 (CheckForLoopClosing and MendMergeAfterLoopClosing, thesis 4.3.6) on Map E with noise,
// two loops (seed 2). While a motion model runs, a group counts as holding a plane in view also
// through the plane's duplicate (another RltPlane global matching finds for the same wall); a
// group holding all of them becomes current, and each plane in view gets a one-way link to its
// duplicate's groups. Here the start wall, mapped in part from the start (plane 0, X0), is seen
// again after the fourth corner as a new plane (plane 9): at 1224 the motion model ends into X0
// through it, and from 1250 Rule 22's chart credits X0 with plane 9 — X0 and X9 then hold three
// of the six planes in view each and the lower id is kept — where without the rule X9 is current
// (the thesis's Fig 101: the old group loses the chart to the new plane's). The link is for
// charting only — the group does not list the plane and the plane has no membership in it — so
// every pose and the final map are bit for bit those of the run without the rule.
TEST(PlaneScenario, Rule37OneWayLinksChartOnlyAndLeaveTheGroupsAlone) {
  sim::PlanarMap map = map_file("e_motion_room.json");
  map.path.loops = 2;
  const sim::PlanarSimulator simulator(map, 2);
  RelativePlaneOptions on;
  on.key_points = true;
  RelativePlaneOptions off = on;
  off.rules.pseudo_merge = false;
  RltXPointsS with(on, simulator.path().world_T_robot(0)), without(off, simulator.path().world_T_robot(0));
  int links = 0, charted_otherwise = 0;
  for (int k = 0; k < simulator.iterations(); ++k) {
    const sim::PlaneSimFrame frame = simulator.frame(k);
    const RelativePlaneStep a = with.step(frame.observation);
    const RelativePlaneStep b = without.step(frame.observation);
    links += a.oneway_links;
    EXPECT_EQ(b.oneway_links, 0);
    ASSERT_EQ(a.pose_valid, b.pose_valid) << "iteration " << k;
    ASSERT_EQ(a.world_T_robot.translation, b.world_T_robot.translation) << "iteration " << k;
    ASSERT_EQ(a.world_T_robot.heading, b.world_T_robot.heading) << "iteration " << k;
    if (a.current_group == b.current_group) continue;
    ++charted_otherwise;
    // Where the charts differ, the group chosen with the rule holds at least as many planes in
    // view as the other, counting the one-way links (RltXPointChart as if merged).
    const auto held = [&](plane::XPointId x) {
      return std::ranges::count_if(a.assignment, [&](plane::PlaneId p) {
        const plane::RltPlane& q = with.planes()[p];
        return q.ref(x) != nullptr || std::ranges::count(q.oneway_xpoints(), x) > 0;
      });
    };
    EXPECT_GE(held(a.current_group), held(b.current_group)) << "iteration " << k;
  }
  EXPECT_GT(charted_otherwise, 0);
  EXPECT_GE(links, 1);
  int found = 0;
  for (const plane::RltPlane& p : with.planes())
    for (plane::XPointId y : p.oneway_xpoints()) {
      ++found;
      EXPECT_EQ(p.ref(y), nullptr) << "plane " << p.id() << " X" << y;
      EXPECT_EQ(std::ranges::count(with.xpoints()[y].planes(), p.id()), 0) << "plane " << p.id() << " X" << y;
    }
  EXPECT_EQ(found, links);
  ASSERT_EQ(with.map().size(), without.map().size());
  for (std::size_t p = 0; p < with.map().size(); ++p) {
    EXPECT_EQ(with.map()[p].mapped, without.map()[p].mapped) << "plane " << p;
    EXPECT_EQ(with.map()[p].plane.a, without.map()[p].plane.a) << "plane " << p;
    EXPECT_EQ(with.map()[p].plane.b, without.map()[p].plane.b) << "plane " << p;
  }
}

// The large frustum (half-angle 35°, 30 deep) keeps walls in view longer, and still
// shows one partial wall at each corner: the whole run (one loop and the partial second that
// closes it) is exact wherever the pose is valid (measured: 2477 of 2501 iterations, 1e-14),
// every one of the 36 walls is mapped with its key-point end exact, and a motion model carried
// each of the five corners. No wall has a second RltPlane: wall 3, seen only in part from the
// start, is seen again on the return beyond the part mapped; global matching (Rule 11, ahead of
// the unassigned list as in the thesis's AddPlane) gives it back to its plane, which grows to the
// whole wall (it used to be the duplicate the thesis keeps on purpose, Fig 90, E15). Wall 2, on
// the map at 3.95 of 4 from the one group that placed it, is later cut at its other end: that end
// of the map entry is not the wall's, and the pose does not use it (MapPlane::holds_end).
TEST(PlaneScenario, MapDLargeFrustumLoopIsExactAndMapsEveryWall) {
  sim::PlanarMap map = noise_free(map_file("d_office_loop.json"));
  map.sensor.frustum = sim::ViewingFrustum::large();
  const SimRun run = run_map(map, 1, noise_free_key_points());
  const Worst w = worst_of(run);
  EXPECT_GE(w.valid, 2450);
  EXPECT_LT(w.position, kNoiseFree);
  EXPECT_LT(w.heading, kNoiseFree);
  EXPECT_EQ(run.motion_models_by.rbegin()->second, 5);
  EXPECT_EQ(run.mapped_of_wall.size(), map.world.walls.size());
  for (const auto& [wall, mapped] : run.mapped_of_wall) EXPECT_EQ(mapped, 1) << "wall " << wall;
  for (const auto& [p, e] : run.final_error) {
    if (run.final_wall.at(p) == 3) {
      EXPECT_NEAR(e.length_ratio, 1, kNoiseFree);
    }
  }
  expect_one_end_exact(run, map);
}

// Map D with the sensor's noise (σ_p 0.01, σ_r 0.3°), large frustum, parts 2 and 3 on
// with their default constants, five seeds. Measured (seeds 1–5): all 36 walls mapped in every
// run; final mean e_ends 0.025–0.041 (noise-free: 0.0085, the parts of walls never seen whole);
// median position error 0.018–0.033 (the pose is taken against a map chained through a dozen
// groups, each link adding its averaging error); no wall with a second plane (before Rule 11 came
// ahead of the unassigned list and the offset test allowed a plane's turn about its midpoint: 1–2,
// a far wall failing Rule 1 in a turn and wall 3 on the return); key points right in 99.9–100 % of the claims (seeds 1–5; a motion model's held end is no claim) — a
// wrong one lasts 20–40 iterations, not the thesis's "about four" (Figs 76–79), until its piece
// ends. Bounds: mean e_ends within the noise-free value plus 10 σ_p; median pose error 5 σ_p.
TEST(PlaneScenario, MapDLargeFrustumWithNoiseMapsEveryWallWithinTheNoise) {
  sim::PlanarMap map = map_file("d_office_loop.json");
  ASSERT_EQ(map.sensor.noise.model, sim::PlaneNoiseModel::Gaussian);
  map.sensor.frustum = sim::ViewingFrustum::large();
  RelativePlaneOptions options;
  options.key_points = true;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const SimRun run = run_map(map, seed, options);
    int complete = 0, duplicated = 0;
    for (const auto& [wall, mapped] : run.mapped_of_wall) {
      complete += mapped >= 1;
      duplicated += mapped > 1;
    }
    EXPECT_EQ(complete, static_cast<int>(map.world.walls.size())) << "seed " << seed;
    EXPECT_EQ(duplicated, 0) << "seed " << seed;
    double ends = 0;
    for (const auto& [p, e] : run.final_error) ends += e.ends;
    const double mean_ends = ends / static_cast<double>(run.final_error.size());
    EXPECT_LT(mean_ends, 0.0085 + 10 * 0.01) << "seed " << seed;
    std::vector<double> position;
    for (const IterationScore& s : run.iterations)
      if (s.pose_valid) position.push_back(s.pose.position);
    ASSERT_GT(position.size(), 2400u) << "seed " << seed;
    std::ranges::nth_element(position, position.begin() + position.size() / 2);
    EXPECT_LT(position[position.size() / 2], 5 * 0.01) << "seed " << seed;
  }
}

// The thesis's Map D (small frustum) with the sensor's noise, seeds 1–5: every wall mapped, and
// the only wall with a second plane is wall 3, seen in part from the start and again on the
// return beyond the part mapped — the duplicate the thesis keeps on purpose (Fig 90, E15).
// Before Rule 11 came ahead of the unassigned list, 4–5 walls a run were mapped twice: on the
// return each re-entered the view as a sliver at the frustum's edge, which a pose error of a few
// hundredths kept below Rule 11's overlap share, became a new RltPlane, and took every later
// observation of its wall. Seed 5 mapped 9 walls twice until Rule 15's tie was widened for short
// pieces (KeyPointTies::small_sample_z: a sliver's cut ends taken as key points at 1776).
// Measured: pose valid 96.2–97.3 %, final mean e_ends 0.138, 0.122, 0.132, 0.198, 0.165 (noise-
// free 0.062: wall 3's first piece and the walls whose far end is never in view). Bound: the
// noise-free value plus 15 σ_p. Seed 4 is the largest: wall 3's return plane is mapped at 0.61 of
// its length, because Rule 18's piece with the most iterations [T] is the one in which it still
// grew (49 against 41 samples seen whole); the walkthrough's largest-size choice maps it whole
// (0.159) but gives seed 5 0.182.
TEST(PlaneScenario, MapDSmallFrustumWithNoiseMapsOnlyWall3Twice) {
  const sim::PlanarMap map = map_file("d_office_loop.json");
  RelativePlaneOptions options;
  options.key_points = true;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const SimRun run = run_map(map, seed, options);
    std::set<int> duplicated;
    for (const auto& [wall, mapped] : run.mapped_of_wall) {
      EXPECT_GE(mapped, 1) << "seed " << seed << " wall " << wall;
      if (mapped > 1) duplicated.insert(wall);
    }
    EXPECT_EQ(run.mapped_of_wall.size(), map.world.walls.size()) << "seed " << seed;
    EXPECT_EQ(duplicated, std::set<int>{3}) << "seed " << seed;
    double ends = 0;
    for (const auto& [p, e] : run.final_error) ends += e.ends;
    EXPECT_LT(ends / static_cast<double>(run.final_error.size()), 0.062 + 15 * 0.01) << "seed " << seed;
    const auto valid = std::ranges::count_if(run.iterations, [](const IterationScore& s) { return s.pose_valid; });
    EXPECT_GT(valid, 2350) << "seed " << seed;
  }
}

// Map E (paper Fig 5, thesis Figs 69, 83–102), noise-free, its own large frustum, both
// loops, parts 2 and 3 on with the noise-free constants above (the interval checks off, their
// default). Every wall is mapped and the pose is exact wherever it is valid (measured: 2841 of
// 2881 iterations, 1e-14); the map holds the one error the thesis accepts:
//  - Rule 17 maps a plane at the largest size it was seen (thesis 4.4.3.11, A47), so a plane never
//    seen whole keeps its key-point end exact and is short by the part never seen. Three are:
//    the inner block's side walls (walls 6, x = 17, and 9, x = 7; z ∈ [5.5, 10.5], 4.5 beside the
//    path, so the 35° frustum shows them from z = 2.5 + 4.5 / tan 35° = 8.927 on: at most 1.573 of
//    5), e_ends ½ (4.5 / tan 35° − 3) = 1.713 each; and plane 0, the start wall seen in part from
//    the start (7.93 of 23, e_ends 7.54), which on the return becomes a second plane mapped whole
//    (plane 9, exact): the duplicate the thesis keeps on purpose (Fig 90, E15). The long walls
//    are never seen whole in one view (at most 20.35 of 23) and are still mapped exactly: the
//    motion model grows them through the turns (Rule 23) and the chained sizes add up (Rule 28).
// The iteration a motion model ends (1235, the first loop's fourth corner) the pose is GetPoset's
// again (Rule 16). It used to grow the start wall's observation (plane 9, 19.41 of 23) from the
// key point of the motion model's membership, whose interval (1157–1235) reaches that iteration:
// key point 1, the west end Rule 23 held while it grew the east end through the turn, but in that
// observation the frustum's cut (1.796 off). A motion model's key point holds for its track as a
// whole, so the pose takes none from it (RltXPointRef::tracked); Rule 19 finds the right one.
TEST(PlaneScenario, MapENoiseFreeTwoLoopsIsExactButForThePartsNeverSeen) {
  const sim::PlanarMap map = noise_free(map_file("e_motion_room.json"));
  ASSERT_EQ(map.path.loops, 2);
  const SimRun run = run_map(map, 1, noise_free_key_points());
  ASSERT_EQ(run.iterations.size(), 2881u);
  const Worst all = worst_of(run);
  EXPECT_GE(all.valid, 2840);
  EXPECT_LT(all.position, kNoiseFree);
  EXPECT_LT(all.heading, kNoiseFree);

  // Every wall mapped; one wall (the start wall) twice.
  EXPECT_EQ(run.mapped_of_wall.size(), map.world.walls.size());
  std::set<int> duplicated;
  for (const auto& [wall, mapped] : run.mapped_of_wall) {
    EXPECT_GE(mapped, 1) << "wall " << wall;
    if (mapped > 1) duplicated.insert(wall);
  }
  EXPECT_EQ(duplicated, std::set<int>{0});
  // Each plane exact in angle and offset, its key-point end exact, never smaller than seen; the
  // ones short of their wall exactly at their largest size seen.
  expect_one_end_exact(run, map);
  std::set<int> partial_walls;
  double final_ends = 0;
  for (const auto& [p, e] : run.final_error) {
    const sim::Wall& wall = map.world.walls.at(run.final_wall.at(p));
    const double length = e.length_ratio * (wall.b - wall.a).norm();
    EXPECT_GE(length, run.longest_seen.at(p) - kNoiseFree) << "plane " << p;
    final_ends += e.ends;
    if (e.length_ratio > 1 - kNoiseFree) continue;
    partial_walls.insert(run.final_wall.at(p));
    EXPECT_NEAR(length, run.longest_seen.at(p), kNoiseFree) << "plane " << p;
  }
  EXPECT_EQ(partial_walls, (std::set<int>{0, 6, 9}));
  // The final map error is the parts never seen: 7.535 + 2 × 1.713.
  EXPECT_NEAR(final_ends, 0.5 * (23 - 7.929629983144714) + 4.5 / std::tan(35 * std::numbers::pi / 180) - 3, 1e-6);
}

// 's checks on Map E, at every corner of both loops (noise-free, as above): as the robot
// nears a corner the side walls leave the 35° frustum and only the end wall is in view, cut on
// both sides, from 1.6 units (32 iterations) before the corner; after three iterations without a
// pose (Rule 26) the motion model starts, and carries the pose through the turn. The end wall
// widens as the robot turns (Rule 23 grows the plane), until its far end comes into view; then
// it shrinks a little — the planar frustum's far corners reach further than straight ahead
// (Fig 89, thesis 4.3.6). The next wall comes into view about 47° into the turn: at the
// corners where it is 13.5 ahead, its end 2 beyond the path, at 82° − 35° = 46.6° (the first
// iteration past it: 48°); where it is 21.5 ahead, at 49.7° (51°). The motion model ends there:
// within min_readings − 1 iterations in the first loop (the new plane is grouped, Rules 8, 12), at
// once in the second (Rule 29: a group holds every plane in view). At the fourth corner the next
// wall, the east wall, is on the map already, but no group holds it with the start wall and it is
// in too many groups to start one (Rule 21's cap): neither Rule 29 nor a new group ends the motion
// model, so the chart's group does, at once (thesis 4.3.6: it ends once a second plane is in view;
// before, it lasted until an inner-block wall that may still start a group came into view, 11 and
// 16 iterations late, and from the third loop on none may: the pose drifted along the start wall).
TEST(PlaneScenario, MapEMotionModelStartsAndEndsWhereSpec37Says) {
  const sim::PlanarMap map = noise_free(map_file("e_motion_room.json"));
  const sim::PlanarSimulator simulator(map, 1);
  const SimRun run = run_map(map, 1, noise_free_key_points());
  const RelativePlaneOptions options = noise_free_key_points();
  const int n = simulator.iterations();
  const auto heading = [&](int k) { return simulator.path().world_T_robot(k).heading; };
  // The turns: [first, last] iterations whose heading differs from the one before.
  std::vector<std::pair<int, int>> turns;
  for (int k = 1; k < n; ++k) {
    if (std::abs(wrap_angle(heading(k) - heading(k - 1))) < 1e-9) continue;
    if (!turns.empty() && turns.back().second == k - 1)
      turns.back().second = k;
    else
      turns.emplace_back(k, k);
  }
  ASSERT_EQ(turns.size(), 8u);
  for (std::size_t c = 0; c < turns.size(); ++c) {
    SCOPED_TRACE("corner " + std::to_string(c));
    const int corner = turns[c].first - 1;  // at the corner, facing the end wall
    // The motion model around this corner: [start, end), end the first iteration without it.
    ASSERT_TRUE(run.iterations[corner].motion_model);
    int start = corner;
    while (run.iterations[start - 1].motion_model) --start;
    int end = corner;
    while (end < n && run.iterations[end].motion_model) ++end;
    // The end wall alone, cut, from `lone` until the next wall comes into view at `enters`.
    const sim::PlaneSimFrame at_corner = simulator.frame(corner);
    ASSERT_EQ(at_corner.truth.planes.size(), 1u);
    const int end_wall = at_corner.truth.planes[0].wall_id;
    int lone = corner;
    while (simulator.frame(lone - 1).truth.planes.size() == 1) --lone;
    int enters = corner;
    while (simulator.frame(enters).truth.planes.size() == 1) ++enters;
    EXPECT_EQ(corner - lone, 32);  // 1.6 units before the corner
    double previous = 0;
    bool far_end_seen = false;
    for (int k = lone; k < enters; ++k) {
      const sim::PlaneSimFrame f = simulator.frame(k);
      ASSERT_EQ(f.truth.planes.size(), 1u) << "iteration " << k;
      EXPECT_EQ(f.truth.planes[0].wall_id, end_wall) << "iteration " << k;
      const double length = f.observation.planes[0].length();
      far_end_seen = far_end_seen || f.truth.planes[0].a_is_wall_end || f.truth.planes[0].b_is_wall_end;
      if (k > corner) {
        // Widening while both ends are cut; then at most 0.1 shorter an iteration (Fig 89).
        EXPECT_GT(length, far_end_seen ? previous - 0.1 : previous) << "iteration " << k;
      }
      previous = length;
    }
    EXPECT_TRUE(far_end_seen);
    const double entry_deg = std::abs(wrap_angle(heading(enters) - heading(corner))) * 180 / std::numbers::pi;
    EXPECT_NEAR(entry_deg, c % 2 == 0 ? 48 : 51, 1e-9);  // "at ψ ≈ 47°"
    // The motion model's start and end.
    EXPECT_EQ(start, lone + options.motion_model.start_after - 1);
    const int late = end - enters;
    EXPECT_GE(late, 0);
    EXPECT_LE(late, c < 4 && c % 4 != 3 ? options.min_readings - 1 : 0);
    for (int k = start; k < end; ++k) EXPECT_TRUE(run.iterations[k].pose_valid) << "iteration " << k;
  }
}

}  // namespace
}  // namespace relslam::eval
