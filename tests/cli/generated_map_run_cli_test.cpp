// One generated map per family (map seed 1, small frustum, noise-free) through Relative Plane
// (docs/generated-maps.md) under the adaptive preset: the pose valid share over the iterations
// with two non-parallel walls in view, and the walls mapped, as floors to raise as Relative Plane
// learns these maps.
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <string>

namespace relslam {
namespace {

struct FamilyRun {
  const char* scenario;
  double least_valid;  // pose valid share over the iterations with two walls > 20 degrees apart in view
  int least_walls;     // walls mapped
};

// Floors a little below what the adaptive preset reaches on map seed 1 (the figures are in
// docs/generated-maps.md). Many valid poses on the rooms, the office and the clutter are still
// wrong (the wrong_valid column counts them); the mirrored corridor has none.
const FamilyRun kFamilies[] = {
    {"gen-convex-room.json", 0.7, 7},         {"gen-inner-walls.json", 0.6, 5}, {"gen-corridor.json", 0.9, 17},
    {"gen-mirrored-corridor.json", 0.95, 18}, {"gen-office.json", 0.9, 36},     {"gen-clutter.json", 0.25, 12},
};

TEST(GeneratedMapRun, EveryFamilyRunsNoiseFreeWithinTodaysBounds) {
  for (const FamilyRun& family : kFamilies) {
    SCOPED_TRACE(family.scenario);
    test::ScratchDir dir;
    const auto r = test::run_relslam({"run", test::source_path(std::string("scenarios/") + family.scenario).string(),
                                      "--out", (dir / "run").string(), "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const test::CsvTable summary = test::read_csv(dir / "run/summary.csv");
    EXPECT_EQ(summary.text(0, "status"), "ok");
    const test::CsvTable its = test::read_csv(dir / "run/relative_plane/iterations.csv");
    int constrained = 0, valid = 0;
    for (std::size_t i = 0; i < its.rows.size(); ++i) {
      if (its.number(i, "truth_wall_angle_deg") <= 20) continue;
      ++constrained;
      valid += its.text(i, "pose_valid") == "1";
    }
    ASSERT_GT(constrained, 100);
    const double share = static_cast<double>(valid) / constrained;
    std::printf("%s: pose valid %.3f of %d iterations with two non-parallel walls in view; %s of %s walls mapped\n",
                family.scenario, share, constrained, summary.text(0, "walls_mapped").c_str(),
                summary.text(0, "walls_seen").c_str());
    EXPECT_GE(share, family.least_valid);
    // The mirrored corridor's pieces, cut by the frustum at the same place on both sides, tie
    // Rule 15 under the thesis's key points (72 % valid, 14 of 18 walls mapped); the adaptive
    // preset takes only the ends the sensor saw as the walls' own, and no valid pose is wrong.
    if (std::string(family.scenario) == "gen-mirrored-corridor.json") {
      EXPECT_EQ(summary.number(0, "wrong_valid"), 0);
    }
    EXPECT_GE(summary.number(0, "walls_mapped"), family.least_walls);
  }
}

}  // namespace
}  // namespace relslam
