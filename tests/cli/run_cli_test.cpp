#include "test_support.hpp"

#include <gtest/gtest.h>
#include <Eigen/Core>

#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>

namespace relslam {
namespace {

using test::run_relslam;

using Table = test::CsvTable;
using test::read_csv;

// Measured times differ from run to run; everything else must not.
bool is_timing(const std::string& column) {
  return column == "runtime_ms" || column.rfind("t_", 0) == 0 || column.rfind("runtime_", 0) == 0 ||
         column == "peak_rss_mb";
}

std::vector<std::string> run_args(const std::filesystem::path& out, std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"run",
                                   test::source_path("scenarios/s-f8.json").string(),
                                   "--out",
                                   out.string(),
                                   "-q",
                                   "--set",
                                   "sim.iterations=400",
                                   "--set",
                                   "sim.density=50",
                                   "--set",
                                   "output.observations_csv=false",
                                   "--set",
                                   "output.rawlog=false"};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

TEST(RunCommand, WritesTheAlgorithmFolderAndSummary) {
  test::ScratchDir dir;
  const auto r = run_relslam(run_args(dir / "run"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Table iterations = read_csv(dir / "run/relative_point/iterations.csv");
  for (const char* column : {"iteration", "landmark_error", "mean_landmark_error", "position_error", "ex", "ey", "ez",
                             "runtime_ms", "t_init_ms", "t_load_ms", "t_compute_ms", "t_create_ms", "t_pose_ms",
                             "visible_points", "landmarks_in_map", "rlt_points", "groups", "final_groups"})
    iterations.column(column);
  EXPECT_EQ(iterations.rows.size(), 400u);
  EXPECT_EQ(test::read_lines(dir / "run/relative_point/trajectory.tum").size(), 400u);
  const Table landmarks = read_csv(dir / "run/relative_point/landmarks.csv");
  EXPECT_EQ(std::vector<std::string>(landmarks.header.begin(), landmarks.header.begin() + 7),
            (std::vector<std::string>{"id", "x", "y", "z", "true_id", "error", "level"}));
  const Table summary = read_csv(dir / "run/summary.csv");
  ASSERT_EQ(summary.rows.size(), 1u);
  EXPECT_EQ(summary.rows[0][summary.column("algorithm")], "relative_point");
  EXPECT_EQ(summary.rows[0][summary.column("status")], "ok");
  for (const char* column : {"final_landmark_error", "final_mean_landmark_error", "final_position_error", "ate_rmse",
                             "runtime_median_ms", "runtime_p95_ms", "runtime_max_ms", "peak_rss_mb"})
    EXPECT_GE(summary.number(0, column), 0.0) << column;
  EXPECT_TRUE(std::filesystem::exists(dir / "run/ground_truth_path.tum"));
}

TEST(RunCommand, FinalLandmarkErrorIsTheSumOfTheMapLandmarksErrors) {
  test::ScratchDir dir;
  ASSERT_EQ(run_relslam(run_args(dir / "run")).exit_code, 0);
  const Table iterations = read_csv(dir / "run/relative_point/iterations.csv");
  const Table landmarks = read_csv(dir / "run/relative_point/landmarks.csv");
  const Table truth = read_csv(dir / "run/ground_truth_landmarks.csv");
  double sum = 0;
  int on_map = 0;
  for (std::size_t i = 0; i < landmarks.rows.size(); ++i) {
    const std::string level = landmarks.rows[i][landmarks.column("level")];
    if (level != "final" && level != "temporary") continue;
    ++on_map;
    sum += landmarks.number(i, "error");
    // The error is the distance to the nearest true landmark (brute force here).
    const Eigen::Vector3d p(landmarks.number(i, "x"), landmarks.number(i, "y"), landmarks.number(i, "z"));
    double nearest = 1e300;
    for (std::size_t j = 0; j < truth.rows.size(); ++j)
      nearest = std::min(
          nearest, (p - Eigen::Vector3d(truth.number(j, "x"), truth.number(j, "y"), truth.number(j, "z"))).norm());
    EXPECT_NEAR(landmarks.number(i, "error"), nearest, 1e-12);
  }
  const std::size_t last = iterations.rows.size() - 1;
  EXPECT_EQ(iterations.number(last, "landmarks_in_map"), on_map);
  EXPECT_NEAR(iterations.number(last, "landmark_error"), sum, 1e-9 * sum);
}

TEST(RunCommand, SameSeedGivesIdenticalResultsApartFromMeasuredTimes) {
  test::ScratchDir dir;
  ASSERT_EQ(run_relslam(run_args(dir / "a")).exit_code, 0);
  ASSERT_EQ(run_relslam(run_args(dir / "b")).exit_code, 0);
  for (const char* file : {"relative_point/landmarks.csv", "relative_point/trajectory.tum", "ground_truth_path.tum"})
    EXPECT_EQ(test::read_file(dir / "a" / file), test::read_file(dir / "b" / file)) << file;
  for (const char* file : {"relative_point/iterations.csv", "summary.csv"}) {
    const Table a = read_csv(dir / "a" / file), b = read_csv(dir / "b" / file);
    ASSERT_EQ(a.header, b.header);
    ASSERT_EQ(a.rows.size(), b.rows.size());
    for (std::size_t r = 0; r < a.rows.size(); ++r)
      for (std::size_t c = 0; c < a.header.size(); ++c)
        if (!is_timing(a.header[c])) {
          ASSERT_EQ(a.rows[r][c], b.rows[r][c]) << file << " row " << r << " " << a.header[c];
        }
  }
}

TEST(RunCommand, NoiseFreeRunScoresZeroErrors) {
  test::ScratchDir dir;
  ASSERT_EQ(run_relslam(
                run_args(dir / "run", {"--set", "sim.noise_sigma=0", "--set", "relative_point.compensated_bound=0.001",
                                       "--set", "relative_point.global_bound=0.001"}))
                .exit_code,
            0);
  const Table iterations = read_csv(dir / "run/relative_point/iterations.csv");
  for (std::size_t r = 0; r < iterations.rows.size(); ++r) {
    ASSERT_LT(iterations.number(r, "mean_landmark_error"), 1e-9) << "row " << r;
    ASSERT_LT(iterations.number(r, "position_error"), 1e-9) << "row " << r;
  }
}

TEST(RunCommand, AScenarioWithoutAlgorithmsIsABadInput) {
  test::ScratchDir dir;
  const auto r = run_relslam(run_args(dir / "run", {"--set", "algorithms=[]"}));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--set: algorithms: the scenario lists no algorithm to run"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace relslam
