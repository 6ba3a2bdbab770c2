// Every input of../shared/reliability/repro run through the relslam program: each
// crashed it, exhausted memory, exited 1 without a location or wrote non-finite numbers. Now each
// must give exit 2 and a message naming the file and line/record in under 5 s and 1 GB. The
// files are used in place (read-only, not copied into the repository); without ../shared the
// tests skip.

#include "located_error.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace relslam {
namespace {

namespace fs = std::filesystem;

fs::path repro_dir() { return test::source_path("../shared/reliability/repro"); }

// Skips every test when the reproducers are not next to the repository.
class ReliabilityRepro : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(repro_dir()))
      GTEST_SKIP() << repro_dir() << " not found: the reproducers live outside the repository";
  }
};

// Exit 2 with `located` in the message, within kQuickRefusalSeconds (5 s) and 1 GB.
void expect_located_error(const std::vector<std::string>& arguments, const std::string& located) {
  test::expect_located_error(arguments, located, test::kQuickRefusalSeconds);
}

std::string repro(const std::string& name) { return (repro_dir() / name).string(); }

TEST_F(ReliabilityRepro, EveryReproducerHasATestHere) {
  const std::set<std::string> covered = {"vp_no_laser_segv",
                                         "rawlog_segv_CActionRobotMovement2D.rawlog",
                                         "set_deep_array_segv.sh",
                                         "scenario_deep_array_20000.json",
                                         "rawlog_count_128m.rawlog",
                                         "rawlog_count_4g.rawlog",
                                         "rawlog_684B_12GB_alloc.rawlog",
                                         "rawlog_sensor_pose_nan.rawlog",
                                         "rawlog_rel3_silent_nonfinite_6446036d87.rawlog",
                                         "rawlog_rel3_silent_nonfinite_a7a7dd2bf0.rawlog",
                                         "rawlog_rel3_silent_nonfinite_c8cb7cdb40.rawlog",
                                         "scenario_number_overflow_1e400.json",
                                         "scn_accrel_2_silent_nonfinite.json",
                                         "scn_accrel_3_silent_nonfinite.json",
                                         "scn_accrel_4_silent_nonfinite.json",
                                         "scn_accrel_5_exit1.json",
                                         "scn_accrel_6_silent_nonfinite.json",
                                         "truth_landmarks_huge_id.txt"};
  for (const fs::directory_entry& e : fs::directory_iterator(repro_dir()))
    EXPECT_TRUE(covered.count(e.path().filename().string())) << e.path() << " has no regression test";
}

TEST_F(ReliabilityRepro, SensorsManagerWithoutALaserLineIsALocatedError) {
  expect_located_error({"victoria-park", test::source_path("scenarios/victoria-park.json").string(), "--data",
                        repro("vp_no_laser_segv"), "--window", "1:1", "--out", "out", "-q"},
                       "vp_no_laser_segv/Sensors_manager.txt: no laser line (sensor 3)");
}

TEST_F(ReliabilityRepro, MutatedOdometryActionIsRefusedBeforeMrptReadsIt) {
  expect_located_error({"rawlog", repro("rawlog_segv_CActionRobotMovement2D.rawlog")},
                       "rawlog_segv_CActionRobotMovement2D.rawlog:");
}

TEST_F(ReliabilityRepro, HugeElementCountsAreRefusedWithoutAllocating) {
  for (const char* name : {"rawlog_count_128m.rawlog", "rawlog_count_4g.rawlog", "rawlog_684B_12GB_alloc.rawlog"}) {
    SCOPED_TRACE(name);
    expect_located_error({"rawlog", repro(name)}, std::string(name) + ":");
  }
}

TEST_F(ReliabilityRepro, NonFiniteRawlogValuesAreRefusedWithRecordAndField) {
  for (const char* name :
       {"rawlog_sensor_pose_nan.rawlog", "rawlog_rel3_silent_nonfinite_6446036d87.rawlog",
        "rawlog_rel3_silent_nonfinite_a7a7dd2bf0.rawlog", "rawlog_rel3_silent_nonfinite_c8cb7cdb40.rawlog"}) {
    SCOPED_TRACE(name);
    expect_located_error({"rawlog", repro(name), "--csv", "x.csv"}, std::string(name) + ":");
  }
}

TEST_F(ReliabilityRepro, DeepArrayInSetScriptExitsTwo) {
  // The script runs build/relslam on scenarios/s-f8.json from the repository root: give it both.
  test::ScratchDir dir;
  fs::create_directory_symlink(RELSLAM_BINARY_DIR, dir / "build");
  fs::create_directory_symlink(test::source_path("scenarios"), dir / "scenarios");
  const test::ProcessResult r = test::run_process({"/bin/bash", repro("set_deep_array_segv.sh")}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("rc=2"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("--set: sim.density: JSON nested deeper than 64 levels"), std::string::npos) << r.err;
  EXPECT_LT(r.seconds, test::kQuickRefusalSeconds);
}

TEST_F(ReliabilityRepro, DeepArrayInAScenarioFileIsRejectedQuickly) {
  expect_located_error({"scenario", repro("scenario_deep_array_20000.json")},
                       "scenario_deep_array_20000.json:1: JSON nested deeper than 64 levels");
}

TEST_F(ReliabilityRepro, NumberBeyondADoubleNamesFileLineAndKey) {
  expect_located_error({"scenario", repro("scenario_number_overflow_1e400.json")},
                       "scenario_number_overflow_1e400.json:1: sim.density: number too large for a double");
}

TEST_F(ReliabilityRepro, HugeWorldLengthsStopAtLoading) {
  const std::pair<const char*, const char*> cases[] = {{"scn_accrel_2_silent_nonfinite.json", "sim.incline_height"},
                                                       {"scn_accrel_3_silent_nonfinite.json", "sim.band_half_width"},
                                                       {"scn_accrel_4_silent_nonfinite.json", "sim.band_half_height"}};
  for (const auto& [name, key] : cases) {
    SCOPED_TRACE(name);
    expect_located_error({"run", repro(name), "--out", "out"}, std::string(name) + ":6: " + key + ": must be <= ");
  }
}

TEST_F(ReliabilityRepro, HugeChartingCapacityStopsAtLoading) {
  expect_located_error({"run", repro("scn_accrel_5_exit1.json"), "--out", "out"},
                       "relative_point.charting_capacity: must be <= ");
}

TEST_F(ReliabilityRepro, SubnormalSensorStdStopsAtLoading) {
  expect_located_error({"victoria-park", repro("scn_accrel_6_silent_nonfinite.json"), "--out", "out"},
                       "ekf2d.std_range: must be >= ");
}

TEST_F(ReliabilityRepro, TruthLandmarkIdOutsideIntIsALocatedError) {
  test::ScratchDir dir;
  ASSERT_EQ(
      test::run_relslam({"run", test::source_path("scenarios/s-ekf-f8.json").string(), "--out", (dir / "sim").string(),
                         "-q", "--set", "sim.iterations=20", "--set", "output.observations_csv=false"})
          .exit_code,
      0);
  std::string path_rows;
  for (int k = 0; k < 20; ++k) path_rows += "0 0 0 0 0 0\n";
  test::write_file(dir / "path.txt", path_rows);
  expect_located_error(
      {"run", "--out", (dir / "log").string(), "-q", "--rawlog", (dir / "sim/observations.rawlog").string(),
       "--truth-path", (dir / "path.txt").string(), "--truth-landmarks", repro("truth_landmarks_huge_id.txt")},
      "truth_landmarks_huge_id.txt:1: id: must be a whole number in the int32 range, got 1e+300");
}

}  // namespace
}  // namespace relslam
