// Generated maps in scenarios (planar.generate; docs/generated-maps.md): the keys, their errors,
// the map file a run writes and its reuse with planar.map, the truth columns of what is in view.
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace relslam {
namespace {

using test::read_csv;
using test::run_relslam;

std::string scenario_with(const std::string& planar) {
  return "{\n  \"kind\": \"planar\",\n  \"planar\": " + planar + ",\n  \"algorithms\": [\"relative_plane\"]\n}\n";
}

TEST(GeneratedMap, KeysAreListedWithThePlanarOnes) {
  const auto r = run_relslam({"keys", "planar"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* key : {"planar.generate.family", "planar.generate.seed", "planar.generate.clearance"})
    EXPECT_NE(r.out.find(key), std::string::npos) << key;
}

TEST(GeneratedMap, AMapFileAndAGeneratedMapExcludeEachOther) {
  test::ScratchDir dir;
  test::write_file(dir / "both.json",
                   scenario_with("{\"map\": \"d_office_loop\",\n    \"generate\": {\"family\": \"office\"}}"));
  const auto r = run_relslam({"simulate", (dir / "both.json").string(), "--out", (dir / "out").string(), "-q"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("both.json:4: planar.generate.family: set either planar.map or planar.generate, not both "
                       "(planar.map at " +
                       (dir / "both.json").string() + ":3)"),
            std::string::npos)
      << r.err;
}

TEST(GeneratedMap, AMisspelledFamilyGetsADidYouMean) {
  test::ScratchDir dir;
  test::write_file(dir / "typo.json", scenario_with("{\"generate\": {\"family\": \"convex_rom\"}}"));
  const auto r = run_relslam({"simulate", (dir / "typo.json").string(), "--out", (dir / "out").string(), "-q"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("typo.json:3: planar.generate.family: expected one of none, convex_room"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("did you mean \"convex_room\"?"), std::string::npos) << r.err;
  const auto clearance = run_relslam({"simulate", test::source_path("scenarios/gen-corridor.json").string(), "--out",
                                      (dir / "c").string(), "-q", "--set", "planar.generate.clearance=3"});
  EXPECT_EQ(clearance.exit_code, 2);
  EXPECT_NE(clearance.err.find("planar.generate.clearance: must be <= 1.2, got 3"), std::string::npos) << clearance.err;
}

// relslam simulate writes the generated map; the same run from that file with planar.map has the
// same walls bit for bit and the same path up to the rounding of its degrees.
TEST(GeneratedMap, SimulateWritesTheMapFileAndItRunsTheSameWithPlanarMap) {
  test::ScratchDir dir;
  const std::string scenario = test::source_path("scenarios/gen-corridor.json").string();
  const auto r = run_relslam({"simulate", scenario, "--out", (dir / "gen").string(), "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::filesystem::path file = dir / "gen/generated_map.json";
  ASSERT_TRUE(std::filesystem::exists(file));
  const auto again = run_relslam({"simulate", scenario, "--out", (dir / "file").string(), "-q", "--set",
                                  "planar.generate.family=none", "--set", "planar.map=" + file.string()});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(test::read_file(dir / "gen/ground_truth_walls.csv"), test::read_file(dir / "file/ground_truth_walls.csv"));
  const test::CsvTable a = read_csv(dir / "gen/ground_truth_poses.csv"), b = read_csv(dir / "file/ground_truth_poses.csv");
  ASSERT_EQ(a.rows.size(), b.rows.size());
  for (std::size_t i = 0; i < a.rows.size(); ++i)
    for (const char* column : {"x", "z"}) EXPECT_NEAR(a.number(i, column), b.number(i, column), 1e-9) << i;
  EXPECT_FALSE(std::filesystem::exists(dir / "file/generated_map.json"));
}

// The truth of what is in view, on generated maps only (the shipped scenarios' files stay as
// they were); a run of a generated map replays for relslam render.
TEST(GeneratedMap, RunsWriteTheTruthInViewAndRender) {
  test::ScratchDir dir;
  const auto r = run_relslam({"run", test::source_path("scenarios/gen-office.json").string(), "--out",
                              (dir / "run").string(), "-q", "--set", "planar.iterations=300"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const test::CsvTable its = read_csv(dir / "run/relative_plane/iterations.csv");
  ASSERT_EQ(its.rows.size(), 300u);
  int crossing = 0;
  for (std::size_t i = 0; i < its.rows.size(); ++i) {
    const double angle = its.number(i, "truth_wall_angle_deg");
    EXPECT_GE(angle, 0.0);
    EXPECT_LE(angle, 90.0 + 1e-9);
    EXPECT_GE(its.number(i, "truth_walls_in_view"), angle > 0 ? 2 : 0);
    crossing += angle > 20;
  }
  EXPECT_GT(crossing, 0) << "the office's corners put two walls at right angles in view";
  const auto png = run_relslam({"render", (dir / "run").string(), "--out", (dir / "map.png").string(), "-q"});
  EXPECT_EQ(png.exit_code, 0) << png.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "map.png"));

  const auto shipped = run_relslam({"run", test::source_path("scenarios/p-hallway.json").string(), "--out",
                                    (dir / "hall").string(), "-q", "--set", "planar.iterations=20"});
  ASSERT_EQ(shipped.exit_code, 0) << shipped.err;
  const test::CsvTable hall = read_csv(dir / "hall/relative_plane/iterations.csv");
  EXPECT_EQ(std::count(hall.header.begin(), hall.header.end(), "truth_wall_angle_deg"), 0);
}

}  // namespace
}  // namespace relslam
