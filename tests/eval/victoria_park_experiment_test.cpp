// The Victoria Park experiment end to end on short windows of the real data (skipped where the
// data is absent), and the stream the algorithms see.
#include "relslam/eval/experiments/victoria_park_experiment.hpp"

#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/io/rawlog.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace relslam::eval {
namespace {

const VictoriaParkLog* data() {
  static const std::filesystem::path dir = test::victoria_park_data();
  static const VictoriaParkLog log = dir.empty() ? VictoriaParkLog{} : read_victoria_park(dir);
  return dir.empty() ? nullptr : &log;
}
#define SKIP_WITHOUT_DATA() \
  if (!data()) GTEST_SKIP() << test::kNoVictoriaPark

LoadedScenario scenario(const std::string& window, std::vector<std::string> set = {}) {
  set.push_back("victoria_park.window=" + window);
  return load_with_overrides(test::source_path("scenarios/victoria-park.json").string(), set);
}

TEST(VictoriaParkStream, TreesBecomeRobotFramePointsInTheScanPlane) {
  VictoriaParkLog log;
  log.scans = {{1, 10.0, {{10.0, std::numbers::pi / 2, 0.3}, {5.0, 0.0, 0.2}, {3.0, 1.0, 0.01}}},
               {2, 10.5, {{8.0, std::numbers::pi, 0.3}}}};
  log.inputs = {{9.0, 2.0, 0.0}};
  LoadedScenario loaded = scenario("1:2", {"victoria_park.min_diameter=0.1"});
  const VictoriaParkStream stream(log, loaded.scenario);
  const ObservationFrame first = stream.frame(log.scans, 0);
  ASSERT_EQ(first.points.size(), 2u);  // the 0.01 m trunk is filtered out
  // Ours: x left, y up, z forward. Straight ahead at 10 m; to the right at 5 m.
  EXPECT_TRUE(first.points[0].isApprox(Eigen::Vector3d(0, 0, 10), 1e-12));
  EXPECT_TRUE(first.points[1].isApprox(Eigen::Vector3d(-5, 0, 0), 1e-12));
  EXPECT_FALSE(first.odometry.has_value());
  const ObservationFrame second = stream.frame(log.scans, 1);
  EXPECT_TRUE(second.points[0].isApprox(Eigen::Vector3d(8, 0, 0), 1e-12));  // to the left
  ASSERT_TRUE(second.odometry.has_value());
  // 0.5 s at 2 m/s straight ahead: 1 m along our +z.
  EXPECT_TRUE(second.odometry->translation.isApprox(Eigen::Vector3d(0, 0, 1), 1e-12));
  EXPECT_EQ(stream.sensor().field_of_view_yaw_rad, std::numbers::pi);
}

TEST(VictoriaParkExperiment, TheRelativeMapAgreesWithTheMapOfTheEkfWithOdometry) {
  SKIP_WITHOUT_DATA();
  test::ScratchDir dir;
  const VictoriaParkResult r =
      run_victoria_park(scenario("1181:1300", {"algorithms=relative_point,ekf2d"}), *data(), dir.path(), false);
  ASSERT_EQ(r.experiment.rows.size(), 2u);
  for (const SummaryRow& row : r.experiment.rows) {
    EXPECT_EQ(row.status.text(), "ok") << row.algorithm;
    EXPECT_EQ(row.iterations, 120) << row.algorithm;
  }
  ASSERT_EQ(r.maps.size(), 1u);
  const MapComparison& m = r.maps[0].second;
  ASSERT_GE(m.landmarks, 10);
  // Both maps start at the same pose and hold the same trunks. A trunk's centre is uncertain by
  // about its radius and the EKF models range noise of 0.5 m: matched trees within that, most
  // of the Relative map matched, and no stretch between the maps (measured: 21 of 21, rms
  // 0.14 m, scale 0.999).
  EXPECT_GE(m.matched, 0.8 * m.landmarks);
  EXPECT_LT(m.rms, 0.5);
  EXPECT_NEAR(m.alignment.scale, 1.0, 0.02);
  // Against GPS, both trajectories within a few metres over 120 scans (~70 m of driving).
  for (const GpsComparison& g : r.gps) {
    EXPECT_GT(g.alignment.pairs, 20) << g.algorithm;
    EXPECT_LT(g.alignment.rmse, 5.0) << g.algorithm;
  }
  for (const char* file : {"scans.csv", "gps.tum", "gps_comparison.csv", "map_comparison.csv", "summary.csv",
                           "relative_point/trajectory_gps_frame.csv", "ekf2d/landmarks_gps_frame.csv",
                           "relative_point/landmarks_similarity_fit.csv"})
    EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
}

// The trees carry no ids: the batch optimum takes its landmarks from Relative Point's run and
// solves every pose and tree of the window; it ends on the same trees as Relative Point and at
// or below its ATE against GPS (window 1181:1642 measured: 1.54 m against 2.56 m under its default
// Cauchy loss, the EKF with odometry 1.52 m).
TEST(VictoriaParkExperiment, TheOptimumTakesItsTreesFromRelativePoint) {
  SKIP_WITHOUT_DATA();
  test::ScratchDir dir;
  const VictoriaParkResult r = run_victoria_park(
      scenario("1181:1300", {"algorithms=relative_point,batch_optimum", "batch_optimum.association=relative_point",
                             "batch_optimum.start=relative_point"}),
      *data(), dir.path(), false);
  ASSERT_EQ(r.gps.size(), 2u);
  for (const SummaryRow& row : r.experiment.rows) {
    if (row.status.text() != "ratio") {
      EXPECT_EQ(row.status.text(), "ok") << row.algorithm;
    }
  }
  const test::CsvTable trees = test::read_csv(dir / "batch_optimum/landmarks.csv");
  EXPECT_GE(trees.rows.size(), 10u);
  EXPECT_EQ(r.gps[1].algorithm, "batch_optimum");
  EXPECT_LE(r.gps[1].alignment.rmse, r.gps[0].alignment.rmse + 1e-9);
}

TEST(VictoriaParkExperiment, RunsAreDeterministic) {
  SKIP_WITHOUT_DATA();
  test::ScratchDir a, b;
  const LoadedScenario loaded = scenario("4220:4300");
  run_victoria_park(loaded, *data(), a.path(), false);
  run_victoria_park(loaded, *data(), b.path(), false);
  for (const char* file : {"relative_point/landmarks.csv", "relative_point/trajectory.tum", "ekf2d/trajectory.tum",
                           "ekf2d_no_odometry/landmarks.csv", "gps_comparison.csv", "map_comparison.csv", "scans.csv"})
    EXPECT_EQ(test::read_file(a / file), test::read_file(b / file)) << file;
}

TEST(VictoriaParkExperiment, TheWholeLogRunsEndToEndWhenBridgedByDeadReckoning) {
  SKIP_WITHOUT_DATA();
  test::ScratchDir dir;
  const VictoriaParkResult r = run_victoria_park(
      scenario("all", {"algorithms=relative_point", "relative_point.use_odometry=true"}), *data(), dir.path(), false);
  EXPECT_EQ(r.scans, 7249);
  EXPECT_EQ(r.scans_below_three, 381);  // scans the thesis's algorithm cannot register
  EXPECT_EQ(r.experiment.rows[0].status.text(), "ok");
  EXPECT_EQ(r.experiment.rows[0].iterations, 7249);
  // Hundreds of trees mapped over the whole park (measured 454; over 500 before dead reckoning
  // checked the registrations).
  EXPECT_GT(r.experiment.rows[0].landmarks_on_map, 300);
  const test::CsvTable rp = test::read_csv(dir / "relative_point/iterations.csv");
  int bridged = 0;
  for (std::size_t i = 0; i < rp.rows.size(); ++i) bridged += rp.text(i, "pose_source") == "odometry";
  EXPECT_GT(bridged, 0);
}

// Dead reckoning checks and stands in for weak registrations (odometry_max_turn_deg,
// odometry_max_shift), and the global bound is 2.5 m: scenarios/victoria-park-bridged.json
// follows GPS over the whole log within the goal of 5 m with the relaxation off and on
// (measured 2.36, 2.58 and 1.78 m; the EKF with odometry 1.50 m; before the gate, 83-137 m).
TEST(VictoriaParkExperiment, TheBridgedWholeLogFollowsGpsWithinFiveMetresWithAndWithoutRelaxation) {
  SKIP_WITHOUT_DATA();
  for (const char* mode : {"off", "on_loop_closure", "periodic"}) {
    test::ScratchDir dir;
    const LoadedScenario loaded =
        load_with_overrides(test::source_path("scenarios/victoria-park-bridged.json").string(),
                            {std::string("relative_point.global_relaxation=") + mode});
    const VictoriaParkResult r = run_victoria_park(loaded, *data(), dir.path(), false);
    ASSERT_EQ(r.gps.size(), 1u);
    EXPECT_GT(r.gps[0].alignment.pairs, 4000) << mode;
    EXPECT_LT(r.gps[0].alignment.rmse, 5.0) << mode;
  }
}

// The global relaxation on the whole log: with the adaptive preset and no bridges a
// periodic solve meets a Levenberg-Marquardt step whose linear solve fails (CHOLMOD: not positive
// definite), which Ceres reported through an uninitialised glog in the middle of the run. The
// solver retries with more damping; the run ends ok and prints nothing.
TEST(VictoriaParkCommand, WholeLogRelaxationPrintsNoSolverWarnings) {
  SKIP_WITHOUT_DATA();
  test::ScratchDir dir;
  const auto r =
      test::run_relslam({"victoria-park", test::source_path("scenarios/victoria-park.json").string(), "--data",
                         test::victoria_park_data().string(), "--window", "all", "--out", (dir / "vp").string(), "-q",
                         "--set", "algorithms=[\"relative_point\"]", "--set", "relative_point.preset=adaptive", "--set",
                         "relative_point.global_relaxation=periodic"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const test::CsvTable rp = test::read_csv(dir / "vp/relative_point/iterations.csv");
  int solves = 0;
  for (std::size_t i = 0; i < rp.rows.size(); ++i) solves += !rp.text(i, "t_relax_ms").empty();
  EXPECT_GT(solves, 10);
}

TEST(ConvertVictoriaPark, TheRawlogCarriesOdometryAndTheTrees) {
  SKIP_WITHOUT_DATA();
  test::ScratchDir dir;
  const auto r = test::run_relslam(
      {"convert", "victoria-park", "--data", test::victoria_park_data().string(), "--window", "1181:1190", "--scenario",
       test::source_path("scenarios/victoria-park.json").string(), "--out", (dir / "vp.rawlog").string(), "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Rawlog log = read_rawlog(dir / "vp.rawlog");
  ASSERT_EQ(log.frames.size(), 10u);
  const LoadedScenario loaded = scenario("1181:1190");
  const auto scans = scans_in(*data(), parse_scan_window("1181:1190", "w"), "w");
  const VictoriaParkStream stream(*data(), loaded.scenario);
  for (std::size_t i = 0; i < log.frames.size(); ++i) {
    const ObservationFrame expected = stream.frame(scans, i);
    const ObservationFrame read = observation_frame(log.frames[i]);
    ASSERT_EQ(read.points.size(), expected.points.size()) << i;
    for (std::size_t j = 0; j < read.points.size(); ++j)
      EXPECT_LT((read.points[j] - expected.points[j]).norm(), 1e-4 * scans[i].trees[j].range) << i;  // float32
    ASSERT_EQ(read.odometry.has_value(), expected.odometry.has_value()) << i;
    if (read.odometry) {
      EXPECT_LT((read.odometry->translation - expected.odometry->translation).norm(), 1e-9) << i;
      EXPECT_TRUE(read.odometry->rotation.isApprox(expected.odometry->rotation, 1e-9)) << i;
    }
    EXPECT_DOUBLE_EQ(log.frames[i].timestamp_s, kSimulationEpoch_s + scans[i].time);
  }
}

TEST(VictoriaParkCommand, MissingDataIsABadInputNamingWhereItLooked) {
  test::ScratchDir dir;
  const auto r = test::run_relslam({"victoria-park", test::source_path("scenarios/victoria-park.json").string(),
                                    "--data", (dir / "nowhere").string(), "--out", (dir / "run").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("nowhere: --data: no Victoria Park data here"), std::string::npos) << r.err;
  const auto window =
      test::run_relslam({"victoria-park", test::source_path("scenarios/victoria-park.json").string(), "--window",
                         "9000:9100", "--data", (dir / "nowhere").string(), "--out", (dir / "run").string()});
  EXPECT_EQ(window.exit_code, 2);
}

}  // namespace
}  // namespace relslam::eval
