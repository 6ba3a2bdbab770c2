// Damaged inputs that ran for minutes, took more than a gigabyte or gave NaN with exit 0: each
// must now stop with exit 2 and a located message, within 20 s and 1 GB. Most tests
// build their input here; the ones named Repro3* run the found inputs of
// ../shared/reliability/repro3 in place and skip when that folder is absent.

#include "located_error.hpp"
#include "relslam/eval/io/rawlog.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace relslam {
namespace {

namespace fs = std::filesystem;

using test::expect_located_error;  // exit 2, the location, within kRefusalSeconds and 1 GB

fs::path repro3_dir() { return test::source_path("../shared/reliability/repro3"); }
std::string repro3(const std::string& name) { return (repro3_dir() / name).string(); }

class Repro3 : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(repro3_dir()))
      GTEST_SKIP() << repro3_dir() << " not found: the reproducers live outside the repository";
  }
};

// ---- scenario files -------------------------------------------------------------------------

// A 20 MB scenario (one flat array of numbers) took 1.5 GB to refuse.
TEST(ReaderLimits, ScenarioAboveTheJsonSizeLimitIsRefusedByItsSize) {
  test::ScratchDir dir;
  std::string text = "{\"description\": [0";
  text.reserve(20'000'010);
  while (text.size() < 20'000'000) text += ",0";
  test::write_file(dir / "big.json", text + "]}");
  expect_located_error({"scenario", (dir / "big.json").string()},
                       (dir / "big.json").string() + ": is 20000002 bytes; a JSON input may be at most 4194304 bytes");
}

// sim.scale up to 1e-5 rounded a loop to zero iterations: 0/0 step length, NaN truth, exit 0.
TEST(ReaderLimits, TinySimScaleIsRefusedAtItsKey) {
  test::ScratchDir dir;
  test::write_file(dir / "t.json", "{\"sim\": {\"iterations\": 20,\n \"scale\": 1e-5}}");
  const test::CliResult r =
      test::run_relslam({"simulate", (dir / "t.json").string(), "--out", (dir / "out").string(), "-q"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("t.json:2: sim.scale: must be >= 0.01"), std::string::npos) << r.err;
  test::write_file(dir / "u.json", "{\"sim\": {\"iterations\": 20, \"iterations_per_loop\": 10,\n \"scale\": 0.05}}");
  const test::CliResult u = test::run_relslam({"scenario", (dir / "u.json").string()});
  EXPECT_EQ(u.exit_code, 2);
  EXPECT_NE(u.err.find("u.json:2: sim.scale: gives less than one iteration per loop"), std::string::npos) << u.err;
}

TEST_F(Repro3, SimScale1e5IsRefusedAtItsKey) {
  expect_located_error({"simulate", repro3("scenario_sim_scale_1e-5_nan_truth.json"), "--out", "out", "-q"},
                       "sim.scale: must be >= 0.01");
}

// ---- rawlogs ---------------------------------------------------------------------------------

// A rawlog from the project's own writer, with the sensor `sensor` describes.
fs::path write_rawlog(const test::ScratchDir& dir, const eval::RangeBearingSensor& sensor) {
  ObservationFrame frame;
  for (int i = 0; i < 5; ++i) frame.points.emplace_back(1.0 + i, 0.5, 10.0);
  eval::RawlogWriter writer(dir / "w.rawlog", sensor, false);
  for (int k = 0; k < 3; ++k) writer.write(frame, {}, eval::kSimulationEpoch_s + k);
  writer.close();
  return dir / "w.rawlog";
}

eval::RangeBearingSensor good_sensor() {
  eval::RangeBearingSensor s;
  s.min_range = 0.1;
  s.max_range = 50;
  s.field_of_view_yaw_rad = 1.5;
  s.field_of_view_pitch_rad = 1.0;
  return s;
}

// A negative field of view ran the EKF for minutes; now the reader refuses it before any run.
TEST(ReaderLimits, RawlogWithANegativeFieldOfViewIsRefused) {
  test::ScratchDir dir;
  eval::RangeBearingSensor sensor = good_sensor();
  const test::CliResult good = test::run_relslam({"rawlog", write_rawlog(dir, sensor).string()});
  EXPECT_EQ(good.exit_code, 0) << good.err;
  sensor.field_of_view_yaw_rad = -1;
  expect_located_error(
      {"run", "--rawlog", write_rawlog(dir, sensor).string(), "--out", "out", "-q", "--set", "algorithms=[\"ekf6d\"]"},
      "w.rawlog:2: fieldOfView_yaw: must be in (0, 2 pi], got -1");
  sensor = good_sensor();
  sensor.max_range = 0.05;
  expect_located_error({"rawlog", write_rawlog(dir, sensor).string()},
                       "w.rawlog:2: maxSensorDistance: must be above minSensorDistance");
}

TEST_F(Repro3, RawlogSensorsThatMakeNoSenseAreRefused) {
  const std::vector<std::string> nn = {"--set", "ekf6d.association=nn", "--set", "algorithms=[\"ekf6d\"]"};
  const std::pair<const char*, const char*> cases[] = {
      {"rawlog_fov_negative_ekf6d_nn_slow.rawlog", "fieldOfView_"},
      {"rawlog_maxrange_below_min_ekf6d_nn_slow.rawlog", "maxSensorDistance: must be above minSensorDistance"},
      {"rawlog_ranges_3e38_ekf6d_nn_slow.rawlog", "beyond the observation's maxSensorDistance"},
      {"rawlog_sensor_x_1e300_ekf6d_nan.rawlog", "sensorLocationOnRobot: each coordinate must be within +-1000 m"}};
  for (const auto& [file, located] : cases) {
    std::vector<std::string> args = {"run", "--rawlog", repro3(file), "--out", "out", "-q"};
    args.insert(args.end(), nn.begin(), nn.end());
    expect_located_error(args, located);
  }
}

TEST_F(Repro3, RawlogOdometryWhoseDifferenceOverflowsIsRefused) {
  expect_located_error({"run", "--rawlog", repro3("rawlog_odometry_increment_overflow.rawlog"), "--out", "out", "-q",
                        "--set", "ekf6d.association=nn", "--set", "algorithms=[\"relative_point\",\"ekf6d\"]", "--set",
                        "relative_point.use_odometry=true"},
                       "CObservationOdometry.odometry");
}

TEST_F(Repro3, RawlogGzipBombIsRefusedByItsDecodedSize) {
  expect_located_error({"rawlog", repro3("rawlog_gzip_bomb_1rec.rawlog.gz")}, "rawlog_gzip_bomb_1rec.rawlog.gz:1: ");
}

// ---- Victoria Park ---------------------------------------------------------------------------

TEST(ReaderLimits, VictoriaParkGpsFileThatIsAFolderIsNamed) {
  test::ScratchDir dir;
  test::write_file(dir / "Sensors_manager.txt", "0.000\t1\t1\n0.852\t3\t1\n");
  test::write_file(dir / "measurements.dat", "0.852 20.0 1.5 0.3\n");
  test::write_file(dir / "inputs.dat", "0.973 0.000 -0.0035\n");
  fs::create_directory(dir / "gps.dat");
  expect_located_error({"victoria-park", test::source_path("scenarios/victoria-park.json").string(), "--data",
                        dir.path().string(), "--window", "1:1", "--out", "out", "-q"},
                       (dir / "gps.dat").string() + ": is a directory, not a data file");
}

TEST_F(Repro3, VictoriaParkGps1e308IsRefusedAtItsLine) {
  expect_located_error({"victoria-park", test::source_path("scenarios/victoria-park.json").string(), "--data",
                        repro3("vp_gps_1e308"), "--window", "all", "--out", "out", "-q"},
                       "gps.dat:8: x: must be within +-1e+06, got 1e+308");
}

// ---- planar maps -----------------------------------------------------------------------------

std::vector<std::string> simulate_room_with(const std::string& map) {
  return {"simulate", test::source_path("scenarios/p-room.json").string(), "--set", "planar.map=" + map, "--out", "out",
          "-q"};
}

// A path through a wall ran with exit 0 and most poses wrong.
TEST(ReaderLimits, PlanarPathThroughAWallIsRefusedWithTheStepAndTheWall) {
  test::ScratchDir dir;
  test::write_file(dir / "m.json",
                   "{\"walls\": [{\"a\": [5, -1], \"b\": [5, 1], \"facing\": \"-x\"},\n"
                   "            {\"a\": [6, 1], \"b\": [6, 2], \"facing\": \"-x\"}],\n"
                   " \"path\": {\"start\": {\"x\": 0, \"z\": 0, \"heading_deg\": 0},\n"
                   "          \"steps\": [\"MOVE 1\",\n \"MOVE 9\"]}}\n");
  expect_located_error(simulate_room_with((dir / "m.json").string()),
                       "m.json:5: path.steps[1]: runs through walls[0] at (5, 0)");
}

// Their paths also run out of their maps (beyond the sensor's reach of every wall), which is
// checked first: a refusal at the path's step, in time that follows the file.
TEST_F(Repro3, PlanarMapsNeverSeeingTwoWallsAreRefusedQuickly) {
  for (const char* name : {"planar_map_200walls_never_seen_10M_path.json", "planar_map_2walls_never_seen_10M_path.json",
                           "planar_map_fuzz_timeout_min.json"})
    expect_located_error(simulate_room_with(repro3(name)), "path.steps[0]: leaves the map at (");
}

}  // namespace
}  // namespace relslam
