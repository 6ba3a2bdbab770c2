// 2-D laser scans in MRPT rawlogs: written with MRPT's own CObservation2DRangeScan and read back,
// bounds checked; MRPT's shipped laser logs read (skipped where mrpt-common is absent), and the
// SENA log through the planar pipeline.
#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/rawlog.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>
#include <mrpt/core/Clock.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <numbers>

namespace relslam::eval {
namespace {

// Scan k: 181 rays over 180°, range 1 + k + i/100 m, every 7th ray without a return.
mrpt::obs::CObservation2DRangeScan scan(int k, bool right_to_left) {
  mrpt::obs::CObservation2DRangeScan obs;
  obs.aperture = static_cast<float>(std::numbers::pi);
  obs.rightToLeft = right_to_left;
  obs.maxRange = 40;
  obs.sensorPose = mrpt::poses::CPose3D(0.2, -0.1, 0.3, 0.05, 0, 0);
  obs.timestamp = mrpt::Clock::fromDouble(1.0e9 + k);
  obs.resizeScan(181);
  for (std::size_t i = 0; i < 181; ++i) {
    obs.setScanRange(i, static_cast<float>(1 + k + static_cast<double>(i) / 100));
    obs.setScanRangeValidity(i, i % 7 != 3);
  }
  return obs;
}

// Action first (odometry x 0.3 m, y 0.1 m, yaw 5° per step), then a frame of one scan.
void write_log(const std::filesystem::path& path, bool right_to_left, int count = 4,
               const std::function<void(mrpt::obs::CObservation2DRangeScan&)>& spoil = {}) {
  mrpt::io::CFileOutputStream file(path.string());
  auto out = mrpt::serialization::archiveFrom(file);
  for (int k = 0; k < count; ++k) {
    mrpt::obs::CActionCollection actions;
    mrpt::obs::CActionRobotMovement2D move;
    move.computeFromOdometry(mrpt::poses::CPose2D(0.3, 0.1, 5 * std::numbers::pi / 180),
                             mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
    actions.insert(move);
    mrpt::obs::CSensoryFrame frame;
    auto obs = std::make_shared<mrpt::obs::CObservation2DRangeScan>(scan(k, right_to_left));
    if (spoil && k == count - 1) spoil(*obs);
    frame.insert(obs);
    out << actions << frame;
  }
}

std::string error_reading(const std::filesystem::path& path) {
  try {
    read_laser_rawlog(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

class LaserRawlogRoundTrip : public ::testing::TestWithParam<bool> {};

TEST_P(LaserRawlogRoundTrip, RangesValidityGeometryAndOdometryComeBack) {
  const bool right_to_left = GetParam();
  test::ScratchDir dir;
  write_log(dir / "scans.rawlog", right_to_left);
  const Rawlog log = read_laser_rawlog(dir / "scans.rawlog");
  EXPECT_TRUE(log.frames.empty());
  ASSERT_EQ(log.scans.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    const RawlogScan& s = log.scans[static_cast<std::size_t>(k)];
    EXPECT_EQ(s.index, k);
    ASSERT_EQ(s.scan.size(), 181u);
    EXPECT_NEAR(s.scan.start_bearing_rad, -std::numbers::pi / 2, 1e-6);
    EXPECT_NEAR(s.scan.bearing_step_rad, std::numbers::pi / 180, 1e-8);
    EXPECT_FLOAT_EQ(static_cast<float>(s.scan.max_range), 40.0f);
    EXPECT_NEAR(s.scan.stamp_s, 1.0e9 + k, 1e-5);
    // MRPT's x, y, yaw become the planar x, z, heading.
    EXPECT_NEAR(s.scan.robot_T_sensor.translation.x(), 0.2, 1e-12);
    EXPECT_NEAR(s.scan.robot_T_sensor.translation.y(), -0.1, 1e-12);
    EXPECT_NEAR(s.scan.robot_T_sensor.heading, 0.05, 1e-12);
    for (std::size_t i = 0; i < 181; ++i) {
      // Our rays run in increasing bearing: MRPT's right-to-left order, or its reverse.
      const std::size_t m = right_to_left ? i : 180 - i;
      EXPECT_EQ(s.scan.valid[i] != 0, m % 7 != 3) << i;
      if (s.scan.valid[i]) {
        EXPECT_FLOAT_EQ(s.scan.ranges[i], static_cast<float>(1 + k + static_cast<double>(m) / 100));
      }
    }
    ASSERT_TRUE(s.odometry.has_value());
    EXPECT_NEAR(s.odometry->translation.x(), 0.3, 1e-9);
    EXPECT_NEAR(s.odometry->translation.y(), 0.1, 1e-9);
    EXPECT_NEAR(s.odometry->heading, 5 * std::numbers::pi / 180, 1e-9);
  }
}

INSTANTIATE_TEST_SUITE_P(ScanDirections, LaserRawlogRoundTrip, ::testing::Bool());

TEST(LaserRawlog, ValuesOutOfBoundsAreRefusedWithTheRecordAndField) {
  test::ScratchDir dir;
  const auto refused = [&](const std::string& name, const std::function<void(mrpt::obs::CObservation2DRangeScan&)>& f) {
    write_log(dir / name, true, 2, f);
    return error_reading(dir / name);
  };
  EXPECT_NE(refused("nan.rawlog", [](auto& o) { o.setScanRange(5, std::nanf("")); }).find(":4: scan[5]: a valid range"),
            std::string::npos);
  EXPECT_NE(refused("far.rawlog", [](auto& o) { o.setScanRange(5, 1e9f); }).find("scan[5]"), std::string::npos);
  // An invalid ray's value is never read.
  EXPECT_EQ(refused("ignored.rawlog", [](auto& o) { o.setScanRange(3, std::nanf("")); }), "(no error)");
  EXPECT_NE(refused("aperture.rawlog", [](auto& o) { o.aperture = -1; }).find("aperture: must be in (0, 2 pi]"),
            std::string::npos);
  EXPECT_NE(refused("range.rawlog", [](auto& o) { o.maxRange = 0; }).find("maxRange"), std::string::npos);
  EXPECT_NE(refused("tilt.rawlog", [](auto& o) { o.sensorPose = mrpt::poses::CPose3D(0, 0, 0, 0, 0.5, 0); })
                .find("sensorPose: the scanner must be level"),
            std::string::npos);
  EXPECT_NE(refused("one.rawlog", [](auto& o) { o.resizeScan(1); }).find("at least 2 rays"), std::string::npos);
}

TEST(LaserRawlog, ALandmarkLogIsNotALaserLog) {
  test::ScratchDir dir;
  write_log(dir / "scans.rawlog", true);
  // And the landmark reader's users are told what a laser log is for.
  const test::CliResult r =
      test::run_relslam({"run", test::source_path("scenarios/s-ekf-f8.json").string(), "--rawlog",
                         (dir / "scans.rawlog").string(), "--out", (dir / "run").string(), "-q"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("feeds the planar half"), std::string::npos) << r.err;
}

std::filesystem::path installed_dataset(const std::string& name) {
  const auto path = mrpt_datasets_folder() / name;
  return std::filesystem::exists(path) ? path : std::filesystem::path();
}

constexpr const char* kSena = "2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog";
// Today's figures on SENA without odometry (docs/laser-scans.md): the wall registration alone
// (wall_odometry, Relative Plane's motion prediction) is 0.24 m (ATE) from ICP-SLAM's path with
// a loop gap of 0.20 m. Relative Plane, comparing the walls by their real ends only (key points
// with open_cut_ends) and placing the walls seen only cut by their lines (place_by_lines), gives
// its own pose on 84 % of the scans, 0.24 m from ICP-SLAM; with the prediction reported where it
// has none, 0.23 m and a loop gap of 0.06 m. Without place_by_lines 43 %: these bounds catch
// its loss. The goal (95 %) is not met yet.
constexpr double kSenaMinValid = 0.75;
constexpr double kSenaMaxAteVsIcp = 0.3;
constexpr double kSenaWallOdometryMaxAte = 0.35;
constexpr double kSenaWallOdometryMaxLoopGap = 0.4;
constexpr double kSenaReportedMaxAteVsIcp = 0.3;
constexpr double kSenaReportedMaxLoopGap = 0.2;

TEST(LaserRawlog, SenaThroughRelativePlaneWithoutOdometry) {
  if (installed_dataset(kSena).empty()) GTEST_SKIP() << kSena << " not installed (Debian package mrpt-common)";
  test::ScratchDir dir;
  const test::CliResult r = test::run_relslam(test::scenario_run_args("real-sena.json", dir / "run", {}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const test::CsvTable summary = test::read_csv(dir / "run/summary.csv");
  ASSERT_EQ(summary.rows.size(), 4u);
  EXPECT_EQ(summary.text(0, "algorithm"), "relative_plane");
  EXPECT_EQ(summary.text(3, "algorithm"), "wall_odometry");
  EXPECT_LE(summary.number(3, "ate_vs_reference"), kSenaWallOdometryMaxAte);
  EXPECT_LE(summary.number(3, "loop_gap_m"), kSenaWallOdometryMaxLoopGap);
  EXPECT_LT(summary.number(3, "ate_vs_reference"), summary.number(2, "ate_vs_reference"));  // beats odometry
  EXPECT_EQ(summary.text(0, "status"), "ok");
  EXPECT_LE(summary.number(0, "ate_vs_reference"), kSenaMaxAteVsIcp);
  EXPECT_EQ(summary.number(1, "ate_vs_reference"), 0);  // ICP-SLAM against itself
  EXPECT_LE(summary.number(1, "loop_gap_m"), 0.3);      // ICP-SLAM closes the loop
  EXPECT_EQ(summary.number(0, "iterations"), 225);
  EXPECT_GE(summary.number(0, "pose_valid_fraction"), kSenaMinValid);
  EXPECT_GE(summary.number(0, "planes_on_map"), 10);
  const std::string ate = summary.text(0, "ate_rmse");  // no ground truth: not scored
  EXPECT_TRUE(ate.empty() || ate == "nan") << ate;
  const test::CsvTable iterations = test::read_csv(dir / "run/relative_plane/iterations.csv");
  EXPECT_EQ(iterations.rows.size(), 225u);
  EXPECT_GT(iterations.number(10, "walls"), 0);
}

// motion_prediction.report_prediction: where Relative Plane has no pose the prediction is the
// robot's, and pose_source says whose each pose is.
TEST(LaserRawlog, SenaWithThePredictionWhereRelativePlaneHasNoPose) {
  if (installed_dataset(kSena).empty()) GTEST_SKIP() << kSena << " not installed (Debian package mrpt-common)";
  test::ScratchDir dir;
  const test::CliResult r = test::run_relslam(test::scenario_run_args(
      "real-sena.json", dir / "run", {"motion_prediction.report_prediction=true"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const test::CsvTable summary = test::read_csv(dir / "run/summary.csv");
  ASSERT_EQ(summary.text(0, "algorithm"), "relative_plane");
  EXPECT_EQ(summary.number(0, "pose_valid_fraction"), 1);
  EXPECT_LE(summary.number(0, "ate_vs_reference"), kSenaReportedMaxAteVsIcp);
  EXPECT_LE(summary.number(0, "loop_gap_m"), kSenaReportedMaxLoopGap);
  const test::CsvTable iterations = test::read_csv(dir / "run/relative_plane/iterations.csv");
  ASSERT_EQ(iterations.rows.size(), 225u);
  int own = 0;
  for (std::size_t k = 0; k < iterations.rows.size(); ++k) {
    const bool valid = iterations.number(k, "pose_valid") != 0;
    EXPECT_EQ(iterations.text(k, "pose_source"), valid ? "algorithm" : "prediction") << k;
    own += valid ? 1 : 0;
  }
  EXPECT_GE(own, kSenaMinValid * 225);
}

}  // namespace
}  // namespace relslam::eval
