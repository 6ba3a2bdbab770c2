// relslam run --rawlog: any MRPT range-bearing rawlog through both algorithms, scored against
// ground truth in MRPT's text formats.
#include "relslam/eval/io/range_bearing.hpp"
#include "relslam/eval/io/rawlog.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace relslam {
namespace {

using test::CsvTable;
using test::read_csv;
using test::run_relslam;

// Our TUM path and landmark CSV as MRPT's simul-landmarks writes them (MRPT axes), in an MRPT
// world frame whose pose relative to our world's origin is `world` (identity: the same origin).
void write_mrpt_truth(const std::filesystem::path& run, const std::filesystem::path& path_txt,
                      const std::filesystem::path& landmarks_txt, const Rigid3& world = Rigid3()) {
  std::ofstream path(path_txt);
  path.precision(17);
  path << "% x y z yaw pitch roll\n";
  for (const std::string& line : test::read_lines(run / "ground_truth_path.tum")) {
    std::istringstream in(line);
    double t, x, y, z, qx, qy, qz, qw;
    in >> t >> x >> y >> z >> qx >> qy >> qz >> qw;
    // Ours -> MRPT's axes: p_m = A^T p_o with p_o = A p_m (a cyclic permutation).
    const Eigen::Matrix3d r_o = Eigen::Quaterniond(qw, qx, qy, qz).normalized().toRotationMatrix();
    Eigen::Matrix3d a;
    a << 0, 1, 0, 0, 0, 1, 1, 0, 0;
    const Eigen::Matrix3d r = world.rotation * a.transpose() * r_o * a;
    const Eigen::Vector3d p = world * eval::mrpt_from_robot({x, y, z});
    path << p.x() << ' ' << p.y() << ' ' << p.z() << ' ' << std::atan2(r(1, 0), r(0, 0)) << ' ' << -std::asin(r(2, 0))
         << ' ' << std::atan2(r(2, 1), r(2, 2)) << '\n';
  }
  std::ofstream landmarks(landmarks_txt);
  landmarks.precision(17);
  const CsvTable truth = read_csv(run / "ground_truth_landmarks.csv");
  for (std::size_t i = 0; i < truth.rows.size(); ++i) {
    const Eigen::Vector3d p =
        world * eval::mrpt_from_robot({truth.number(i, "x"), truth.number(i, "y"), truth.number(i, "z")});
    landmarks << p.x() << ' ' << p.y() << ' ' << p.z() << " 0 0 0 " << truth.text(i, "id") << '\n';
  }
}

std::vector<std::string> small_ekf_run(const std::filesystem::path& out) {
  return {"run",
          test::source_path("scenarios/s-ekf-f8.json").string(),
          "--out",
          out.string(),
          "-q",
          "--set",
          "sim.iterations=150",
          "--set",
          "output.observations_csv=false"};
}

TEST(RunRawlog, RecordedObservationsScoreAsTheSimulatedOnes) {
  test::ScratchDir dir;
  ASSERT_EQ(run_relslam(small_ekf_run(dir / "sim")).exit_code, 0);
  write_mrpt_truth(dir / "sim", dir / "path.txt", dir / "landmarks.txt");
  const auto r =
      run_relslam({"run", test::source_path("scenarios/s-ekf-f8.json").string(), "--out", (dir / "log").string(), "-q",
                   "--rawlog", (dir / "sim/observations.rawlog").string(), "--truth-path", (dir / "path.txt").string(),
                   "--truth-landmarks", (dir / "landmarks.txt").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const CsvTable simulated = read_csv(dir / "sim/summary.csv"), recorded = read_csv(dir / "log/summary.csv");
  ASSERT_EQ(recorded.rows.size(), 3u);  // relative_point, ekf6d, their ratio
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(recorded.text(i, "algorithm"), simulated.text(i, "algorithm"));
    EXPECT_EQ(recorded.text(i, "status"), "ok");
    EXPECT_EQ(recorded.text(i, "iterations"), "150");
    // The rawlog stores single-precision measurements: close, not bit-equal.
    for (const char* column : {"final_mean_landmark_error", "final_position_error", "ate_rmse"})
      EXPECT_NEAR(recorded.number(i, column), simulated.number(i, column), 1e-3 + 0.02 * simulated.number(i, column))
          << recorded.text(i, "algorithm") << " " << column;
    EXPECT_EQ(recorded.text(i, "landmarks_on_map"), simulated.text(i, "landmarks_on_map"));
  }
  EXPECT_EQ(recorded.text(0, "input_digest"), recorded.text(1, "input_digest"));
}

TEST(RunRawlog, WithoutTruthTheRunStillMapsAndSaysWhatItCannotScore) {
  test::ScratchDir dir;
  ASSERT_EQ(run_relslam(small_ekf_run(dir / "sim")).exit_code, 0);
  const auto r = run_relslam(
      {"run", "--out", (dir / "log").string(), "-q", "--rawlog", (dir / "sim/observations.rawlog").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const CsvTable summary = read_csv(dir / "log/summary.csv");
  ASSERT_GE(summary.rows.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(summary.text(i, "status"), "ok");
    EXPECT_GT(summary.number(i, "landmarks_on_map"), 10);
    EXPECT_EQ(summary.text(i, "final_position_error"), "") << "no truth: no number";
  }
}

TEST(RunRawlog, ATruthPathShorterThanTheLogIsABadInput) {
  test::ScratchDir dir;
  ASSERT_EQ(run_relslam(small_ekf_run(dir / "sim")).exit_code, 0);
  test::write_file(dir / "path.txt", "0 0 0 0 0 0\n");
  const auto r = run_relslam({"run", "--out", (dir / "log").string(), "-q", "--rawlog",
                              (dir / "sim/observations.rawlog").string(), "--truth-path", (dir / "path.txt").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("path.txt: --truth-path: 1 rows for 150 frames"), std::string::npos) << r.err;
}

// A rawlog run writes the truth it was given as a simulated run has it (our axes and world,
// the log's times), its trajectories carry the log's times, and `relslam convert tum` puts them
// back into MRPT's axes and world frame: the truth path then equals MRPT's truth file row by row.
TEST(RunRawlog, TruthFilesAndTrajectoriesCarryTheLogsTimesAndConvertGivesMrptsFrame) {
  test::ScratchDir dir;
  ASSERT_EQ(run_relslam(small_ekf_run(dir / "sim")).exit_code, 0);
  const Rigid3 world{Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix(), {5, -2, 1}};
  write_mrpt_truth(dir / "sim", dir / "path.txt", dir / "landmarks.txt", world);
  const auto r = run_relslam({"run", "--out", (dir / "log").string(), "-q", "--rawlog",
                              (dir / "sim/observations.rawlog").string(), "--truth-path", (dir / "path.txt").string(),
                              "--truth-landmarks", (dir / "landmarks.txt").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto simulated = test::read_lines(dir / "sim/ground_truth_path.tum");
  const auto recorded = test::read_lines(dir / "log/ground_truth_path.tum");
  const auto estimated = test::read_lines(dir / "log/relative_point/trajectory.tum");
  ASSERT_EQ(recorded.size(), 150u);
  ASSERT_EQ(estimated.size(), 150u);
  for (std::size_t k = 0; k < recorded.size(); ++k) {
    std::istringstream sim_row(simulated[k]), log_row(recorded[k]), est_row(estimated[k]);
    double st, sx, sy, sz, lt, lx, ly, lz, et;
    sim_row >> st >> sx >> sy >> sz;
    log_row >> lt >> lx >> ly >> lz;
    est_row >> et;
    EXPECT_DOUBLE_EQ(lt, eval::kSimulationEpoch_s + static_cast<double>(k)) << "the log's time, row " << k;
    EXPECT_DOUBLE_EQ(et, lt) << "row " << k;
    EXPECT_NEAR((Eigen::Vector3d(lx, ly, lz) - Eigen::Vector3d(sx, sy, sz)).norm(), 0, 1e-9) << "row " << k;
  }
  const CsvTable true_landmarks = read_csv(dir / "log/ground_truth_landmarks.csv");
  const CsvTable sim_landmarks = read_csv(dir / "sim/ground_truth_landmarks.csv");
  ASSERT_EQ(true_landmarks.rows.size(), sim_landmarks.rows.size());
  for (std::size_t i = 0; i < true_landmarks.rows.size(); ++i) {
    EXPECT_EQ(true_landmarks.text(i, "log_id"), sim_landmarks.text(i, "id"));
    EXPECT_NEAR(true_landmarks.number(i, "z"), sim_landmarks.number(i, "z"), 1e-9);
  }

  ASSERT_EQ(run_relslam({"convert", "tum", (dir / "log").string(), "--out", (dir / "mrpt").string()}).exit_code, 0);
  const auto converted = test::read_lines(dir / "mrpt/ground_truth_path.tum");
  const auto mrpt_rows = test::read_lines(dir / "path.txt");  // a comment line, then x y z yaw pitch roll
  ASSERT_EQ(converted.size() + 1, mrpt_rows.size());
  for (std::size_t k = 0; k < converted.size(); ++k) {
    std::istringstream ours(converted[k]), theirs(mrpt_rows[k + 1]);
    double t, x, y, z, mx, my, mz;
    ours >> t >> x >> y >> z;
    theirs >> mx >> my >> mz;
    EXPECT_NEAR((Eigen::Vector3d(x, y, z) - Eigen::Vector3d(mx, my, mz)).norm(), 0, 1e-9) << "row " << k;
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "mrpt/relative_point/trajectory.tum"));
  EXPECT_TRUE(std::filesystem::exists(dir / "mrpt/ekf6d/trajectory.tum"));
}

// MRPT's own 6D EKF-SLAM demo log, where the mrpt-common package is installed.
TEST(RunRawlog, MrptsSixDofDemoLogRunsThroughBothAlgorithms) {
  const std::filesystem::path demo = "/usr/share/mrpt/datasets/kf-slam_6D_demo.rawlog";
  if (!std::filesystem::exists(demo)) GTEST_SKIP() << demo << " not installed (apt-get install mrpt-common)";
  test::ScratchDir dir;
  const auto r = run_relslam({"run", "--out", (dir / "demo").string(), "-q", "--rawlog", demo.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const CsvTable summary = read_csv(dir / "demo/summary.csv");
  ASSERT_GE(summary.rows.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(summary.text(i, "status"), "ok") << summary.text(i, "algorithm");
    EXPECT_GT(summary.number(i, "landmarks_on_map"), 0) << summary.text(i, "algorithm");
  }
}

}  // namespace
}  // namespace relslam
