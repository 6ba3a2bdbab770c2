// One generated map per family (map seed 1, small frustum, noise-free) through Relative Plane
// (docs/generated-maps.md): the pose valid share over the iterations with two non-parallel walls
// in view, the walls mapped, and the poses called valid that are wrong.
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace relslam {
namespace {

struct FamilyRun {
  const char* scenario;
  double least_valid;  // pose valid share over the iterations with two walls > 20 degrees apart in view
  int least_walls;     // walls mapped
};

// Floors at about half of what the adaptive preset reaches on map seed 1 today (the figures are
// in docs/generated-maps.md); many of its valid poses there are still wrong, which the
// wrong_valid column counts (relative_plane.grounded_map removes them, below).
const FamilyRun kFamilies[] = {
    {"gen-convex-room.json", 0.08, 3}, {"gen-inner-walls.json", 0.008, 2},       {"gen-corridor.json", 0.5, 15},
    {"gen-mirrored-corridor.json", 0.35, 10}, {"gen-office.json", 0.25, 25}, {"gen-clutter.json", 0.35, 10},
};

// One run of a generated map's scenario (with `--set` overrides): the pose valid share over the
// iterations with two walls > 20 degrees apart in view, and the summary's walls and wrong poses.
struct GeneratedRun {
  double valid_share = 0;
  int constrained = 0;
  double walls_mapped = 0;
  double wrong_valid = 0;
  double worst_valid_error = 0;  // the largest position error of a valid pose
};

GeneratedRun run_generated(const std::string& scenario, const std::vector<std::string>& sets = {}) {
  test::ScratchDir dir;
  std::vector<std::string> args = {"run", test::source_path("scenarios/" + scenario).string(), "--out",
                                   (dir / "run").string(), "-q"};
  for (const std::string& set : sets) args.insert(args.end(), {"--set", set});
  const auto r = test::run_relslam(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  if (r.exit_code != 0) return {};
  const test::CsvTable summary = test::read_csv(dir / "run/summary.csv");
  // Finished: ok, or scored lost by the truth check (gen-convex-room and gen-office with the
  // adaptive preset today, whose hundreds of wrong valid poses keep the position 1.5 to 5 off for
  // 50 iterations and more), never failed.
  const std::string status = summary.text(0, "status");
  EXPECT_TRUE(status == "ok" || status.rfind("lost: left the truth at iteration ", 0) == 0) << status;
  const test::CsvTable its = test::read_csv(dir / "run/relative_plane/iterations.csv");
  GeneratedRun out;
  int valid = 0;
  // A map file's scenario (not generated) has no truth columns: then only the valid poses' errors.
  const bool angles = std::ranges::find(its.header, "truth_wall_angle_deg") != its.header.end();
  for (std::size_t i = 0; i < its.rows.size(); ++i) {
    if (its.text(i, "pose_valid") == "1")
      out.worst_valid_error = std::max(out.worst_valid_error, its.number(i, "position_error"));
    if (!angles || its.number(i, "truth_wall_angle_deg") <= 20) continue;
    ++out.constrained;
    valid += its.text(i, "pose_valid") == "1";
  }
  out.valid_share = out.constrained > 0 ? static_cast<double>(valid) / out.constrained : 0;
  out.walls_mapped = summary.number(0, "walls_mapped");
  out.wrong_valid = summary.number(0, "wrong_valid");
  std::printf("%s: pose valid %.3f of %d iterations with two non-parallel walls in view; %s of %s walls mapped; "
              "%s wrong valid\n",
              scenario.c_str(), out.valid_share, out.constrained, summary.text(0, "walls_mapped").c_str(),
              summary.text(0, "walls_seen").c_str(), summary.text(0, "wrong_valid").c_str());
  return out;
}

TEST(GeneratedMapRun, EveryFamilyRunsNoiseFreeWithinTodaysBounds) {
  for (const FamilyRun& family : kFamilies) {
    SCOPED_TRACE(family.scenario);
    const GeneratedRun run = run_generated(family.scenario);
    ASSERT_GT(run.constrained, 100);
    EXPECT_GE(run.valid_share, family.least_valid);
    EXPECT_GE(run.walls_mapped, family.least_walls);
  }
}

// relative_plane.grounded_map on the noise-free maps: no pose called valid is off the truth by
// more than the wrong-valid bound, and where stated every valid pose is exact. Without it (motion-
// model guesses and mismatched wall pieces on the map), the convex room had 226 wrong valid
// poses (up to 2.6 off), the corridor 111, the office 259, the clutter 701 (1236, 118, 622 and 357
// with open_cut_ends).
struct IntegrityRun {
  const char* scenario;
  bool open_cut_ends;
  bool exact;  // every valid pose within 1e-6 of the truth
};

void expect_integrity(std::initializer_list<IntegrityRun> runs) {
  for (const IntegrityRun& r : runs) {
    SCOPED_TRACE(std::string(r.scenario) + (r.open_cut_ends ? " open_cut_ends" : ""));
    const GeneratedRun run =
        run_generated(r.scenario, {"relative_plane.grounded_map=true",
                                   std::string("relative_plane.open_cut_ends=") + (r.open_cut_ends ? "true" : "false")});
    ASSERT_GT(run.constrained, 100);
    EXPECT_EQ(run.wrong_valid, 0);
    if (r.exact) {
      EXPECT_GT(run.valid_share, 0);
      EXPECT_LT(run.worst_valid_error, 1e-6);
    }
  }
}

TEST(GeneratedMapRun, NoWrongPoseCalledValidInRoomsAndCorridors) {
  expect_integrity({{"gen-convex-room.json", true, true},
                    {"gen-convex-room.json", false, true},
                    {"gen-corridor.json", true, true},
                    {"gen-corridor.json", false, true},
                    {"gen-inner-walls.json", true, false}});
}

TEST(GeneratedMapRun, NoWrongPoseCalledValidInOfficesAndClutter) {
  expect_integrity({{"gen-office.json", true, true},
                    {"gen-office.json", false, false},
                    {"gen-clutter.json", true, true},
                    {"gen-mirrored-corridor.json", false, false}});
}

// grounded_map with open_cut_ends, small frustum: every valid pose exact, and the valid share
// over the iterations with two non-parallel walls in view at least about half of today's
// (docs/generated-maps.md: corridor 2.0 %, office 15.7 %, mirrored corridor 98.2 % with valid
// poses up to 0.0055 off from its ties). What keeps the rest invalid is that no group is made
// after the first few hundred iterations (the table there), not a wrong map.
TEST(GeneratedMapRun, GroundedMapKeepsItsValidPosesExactWithTheSmallFrustum) {
  struct Bound {
    const char* scenario;
    double least_valid;
    double worst_error;
  };
  for (const Bound& b : {Bound{"gen-office.json", 0.08, 1e-6}, Bound{"gen-corridor.json", 0.01, 1e-6},
                         Bound{"gen-mirrored-corridor.json", 0.9, 0.01}}) {
    SCOPED_TRACE(b.scenario);
    const GeneratedRun run =
        run_generated(b.scenario, {"relative_plane.grounded_map=true", "relative_plane.open_cut_ends=true"});
    ASSERT_GT(run.constrained, 100);
    EXPECT_EQ(run.wrong_valid, 0);
    EXPECT_GE(run.valid_share, b.least_valid);
    EXPECT_LT(run.worst_valid_error, b.worst_error);
  }
}

// relative_plane.observed_anchor (beyond Rule 4): the room at 30 and 120 degrees with the small
// frustum starts facing its bottom wall and the inner wall, parallel, each cut at both ends by the
// frustum. Anchored on those first readings (the adaptive preset's default) every later pose is
// off along them, up to 4 units, and still called valid; with the key X0 waits for an uncut end or
// a corner in its first readings, none comes, and no pose rests on the guess.
TEST(GeneratedMapRun, X0NeverRestsOnFirstWallsCutAtBothEnds) {
  const std::vector<std::string> room = {"planar.frustum=small", "planar.noise.model=none"};
  const GeneratedRun guessed = run_generated("p-i-room-30-120.json", room);
  EXPECT_GT(guessed.wrong_valid, 100);
  EXPECT_GT(guessed.worst_valid_error, 1.0);
  std::vector<std::string> anchored = room;
  anchored.push_back("relative_plane.observed_anchor=true");
  const GeneratedRun waited = run_generated("p-i-room-30-120.json", anchored);
  EXPECT_EQ(waited.wrong_valid, 0);
  EXPECT_LT(waited.worst_valid_error, 1e-6);
}

// relative_plane.open_cut_ends (experimental, off by default): on the mirrored corridor,
// whose pieces the frustum cuts at the same place on both sides (Rule 15's tie), key points on
// the walls' own ends map every wall and keep the pose valid nearly throughout, with no wrong
// pose called valid; off, the tie leaves walls unmapped and the pose invalid more often
// (docs/experiments/relative-plane-integrity.md).
TEST(GeneratedMapRun, OpenCutEndsMapsTheMirroredCorridor) {
  const GeneratedRun open = run_generated("gen-mirrored-corridor.json", {"relative_plane.open_cut_ends=true"});
  ASSERT_GT(open.constrained, 100);
  EXPECT_GE(open.valid_share, 0.95);
  EXPECT_EQ(open.walls_mapped, 18);
  EXPECT_EQ(open.wrong_valid, 0);

  const GeneratedRun off = run_generated("gen-mirrored-corridor.json", {"relative_plane.open_cut_ends=false"});
  EXPECT_EQ(off.constrained, open.constrained);
  EXPECT_LT(off.valid_share, 0.9);
  EXPECT_LT(off.walls_mapped, 18);
}

}  // namespace
}  // namespace relslam
