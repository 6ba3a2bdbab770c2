// Bad input to the readers of the range sensors, the point clouds and the plane files, each a
// case that crashed, ran away or was accepted as nonsense: each must now stop with exit 2 and a
// located message (file:line or record: field: problem), within a time bound and 1 GB. The
// inputs the fuzzers found (tests/fuzz/README.md) are run from the seed corpora in place.

#include "located_error.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace relslam {
namespace {

using test::expect_located_error;  // exit 2, the location, within kRefusalSeconds and 1 GB

std::string corpus(const std::string& file) { return test::source_path("tests/fuzz/corpus/" + file).string(); }

// `relslam extract --rawlog file`: exit 2 with `located`.
void expect_extract_refused(const std::string& file, const std::string& located) {
  expect_located_error({"extract", "--rawlog", file, "--out", "x", "--extractors", "em2", "--quiet"}, located);
  expect_located_error({"rawlog", file}, located);
}

// ---- point-cloud rawlogs ----------------------------------------------------------------------

// Velodyne raw packets without the sensor's calibration: MRPT's decoder threw its own
// assertion (laserId < num_lasers), printed with its call stack, exit 1.
TEST(BadInput, VelodynePacketsWithoutCalibrationAreRefusedAtTheField) {
  const std::string file = corpus("point_cloud/found_velodyne_no_calibration.rawlog");
  expect_extract_refused(file, file + ":1: CObservationVelodyneScan.calibration: raw packets need the calibration");
}

// ---- point files (relslam extract --points) ------------------------------------------------

// `relslam extract --points name` with the given text: exit 2 with "name:" + `located`.
void expect_points_refused(const std::string& name, const std::string& text, const std::string& located) {
  test::ScratchDir dir;
  test::write_file(dir / name, text);
  expect_located_error({"extract", "--points", (dir / name).string(), "--out", (dir / "x").string(), "--extractors",
                        "em2", "--quiet"},
                       name + located);
}

// Open3D sized the cloud to the header's count before reading: a PCD stating 10^8 points over
// one data line took 5 GB and 108 s and gave 10^8 points at the origin (exit 0); a PLY stating
// 2·10^9 vertices threw bad_alloc (exit 1); a PLY without y left it uninitialised.
TEST(BadInput, PointFileHeadersAreCheckedBeforeOpen3dReadsThem) {
  const std::string pcd = "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
  expect_points_refused("a.pcd", pcd + "WIDTH 9999999\nHEIGHT 1\nPOINTS 9999999\nDATA ascii\n1 2 3\n",
                        ":8: POINTS: 9999999 points, the data has 1 lines");
  expect_points_refused("b.pcd", pcd + "WIDTH 99999999\nHEIGHT 1\nPOINTS 99999999\nDATA ascii\n1 2 3\n",
                        ":6: WIDTH: must be in [1, 16777216]");
  expect_points_refused("c.pcd", pcd + "WIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA binary\n0123456789",
                        ":9: DATA: 2 points need 24 bytes, the file has 10");
  expect_points_refused("d.pcd", "FIELDS x y z\nSIZE 8 8 8\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2 3\n",
                        ":1: FIELDS x: type F of 8 bytes");
  const std::string ply = "ply\nformat ascii 1.0\nelement vertex ";
  expect_points_refused("a.ply", ply + "2000000000\nproperty float x\nproperty float y\nproperty float z\nend_header\n",
                        ":3: element vertex: must be in [1, 16777216]");
  expect_points_refused("b.ply", ply + "2\nproperty float x\nproperty float z\nend_header\n1 2\n3 4\n",
                        ":3: element vertex: needs exactly one scalar property y");
}

// A compressed PCD whose sizes agree with its header but whose data does not decompress: Open3D
// printed its warning in colour on stdout, where relslam writes its tables; now nothing of
// Open3D's reaches stdout, and relslam's own message names the file.
TEST(BadInput, Open3dsMessagesStayOffStdout) {
  test::ScratchDir dir;
  std::string pcd = "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1\nHEIGHT 1\nPOINTS 1\n";
  pcd += "DATA binary_compressed\n";
  const std::uint32_t sizes[2] = {4, 12};  // compressed, uncompressed: one point of three floats
  pcd.append(reinterpret_cast<const char*>(sizes), sizeof sizes);
  pcd += "\xff\xff\xff\xff";
  test::write_file(dir / "e.pcd", pcd);
  const auto r = test::run_relslam({"extract", "--points", (dir / "e.pcd").string(), "--out", (dir / "x").string(),
                                    "--extractors", "em2"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.out.find('\x1b'), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("Open3D"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("e.pcd: Open3D cannot read it as a point cloud"), std::string::npos) << r.err;
  // Open3D's reason, on stderr without its colour codes.
  EXPECT_NE(r.err.find("relslam: [Open3D WARNING] Read PCD failed: unable to read data."), std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
}

// ---- plane files (relslam run --planes) ---------------------------------------------------------

const char* const kHeader = "iteration,index,kp1_x,kp1_z,kp2_x,kp2_z";

// `relslam run --planes planes.csv [extra]` with the given file text: exit 2 with `located`
// (the scratch folder's file name followed by it).
void expect_planes_refused(const std::string& planes, const std::string& located,
                           const std::vector<std::pair<std::string, std::string>>& truth = {}) {
  test::ScratchDir dir;
  test::write_file(dir / "planes.csv", planes);
  std::vector<std::string> args = {"run", "--planes", (dir / "planes.csv").string(), "--out", (dir / "run").string(),
                                   "-q"};
  for (const auto& [flag, text] : truth) {
    test::write_file(dir / (flag.substr(2) + ".csv"), text);
    args.insert(args.end(), {flag, (dir / (flag.substr(2) + ".csv")).string()});
  }
  expect_located_error(args, located);
}

// One row at iteration 9,999,999 held ten million empty frames: 89 s and 3.1 GB, then exit 0.
TEST(BadInput, PlaneFileWithAnIterationFarAheadIsRefusedAtItsLine) {
  expect_planes_refused(std::string(kHeader) + "\n0,0,1,2,3,4\n9999999,0,1,2,3,4\n",
                        "planes.csv:3: iteration: 9999998 iterations without a plane since the previous row");
}

// Accepted and run with status ok: planes 1e300 away (map empty), an upside-down height range,
// a true_wall that truncated to another int, a true wall that is not among the truth walls.
TEST(BadInput, PlaneFileWithNonsenseValuesIsRefusedAtTheColumn) {
  const std::string h = kHeader;
  expect_planes_refused(h + "\n0,0,1e300,2,-1e300,4\n", "planes.csv:2: kp1_x: beyond +-1e+06 m, got 1e+300");
  expect_planes_refused(h + ",y_lo,y_hi\n0,0,1,2,3,4,0,2\n1,0,1,2,3,4,2,1\n",
                        "planes.csv:3: y_hi: the height range must not be upside down");
  expect_planes_refused(h + ",true_wall\n0,0,1,2,3,4,99999999999\n",
                        "planes.csv:2: true_wall: expected -1 (unknown) or 0 to 100000");
  expect_planes_refused(h + ",true_wall\n0,0,1,2,3,4,0\n0,1,1,2,3,5,2\n",
                        "planes.csv:3: true_wall: wall 2 is not in the truth walls",
                        {{"--truth-walls", "id,a_x,a_z,b_x,b_z,height\n0,-3,4,3,4,2.5\n1,3,4,3,-1,2.5\n"}});
}

// Truth walls a map file may not hold (a repeated id overwrote the first wall, a wall without
// length or height was scored against) and a truth pose out of reach: accepted, exit 0.
TEST(BadInput, PlaneFileTruthIsHeldToTheMapRules) {
  const std::string planes = std::string(kHeader) + "\n0,0,1,2,3,4\n";
  const std::string walls = "id,a_x,a_z,b_x,b_z,height\n0,-3,4,3,4,2.5\n";
  expect_planes_refused(planes, "truth-walls.csv:3: id: repeats the id 0",
                        {{"--truth-walls", walls + "0,3,4,3,-1,2.5\n"}});
  expect_planes_refused(planes, "truth-walls.csv:3: b_x: equals a [3, 4]",
                        {{"--truth-walls", walls + "1,3,4,3,4,2.5\n"}});
  expect_planes_refused(planes, "truth-walls.csv:3: height: must be > 0, got -2.5",
                        {{"--truth-walls", walls + "1,3,4,3,-1,-2.5\n"}});
  expect_planes_refused(planes, "truth-path.csv:2: x: beyond +-1e+06 m",
                        {{"--truth-path", "iteration,x,z,heading_rad\n0,-1e300,0,0\n"}});
}

// ---- scenario keys of the laser and optimum baselines --------------------------------------------

// icp_slam.threshold_dist 1e300: MRPT shrank it by alfa for minutes per scan (a 40-scan run had
// not ended after 5 minutes); alfa 1: MRPT's assertion (alfa < 1) became the run's status with
// its stack trace; a start perturbation of 1e300 ran and failed instead of being refused.
TEST(BadInput, BaselineKeysOutOfRangeAreRefusedAtTheKey) {
  const std::string laser = test::source_path("scenarios/p-laser-room.json").string();
  const auto refused = [&](const std::string& scenario, const std::string& set, const std::string& located) {
    expect_located_error({"run", scenario, "--set", set, "--out", "x", "-q"}, located);
  };
  refused(laser, "icp_slam.threshold_dist=1e300", "icp_slam.threshold_dist: must be <= 100, got 1e+300");
  refused(laser, "icp_slam.alfa=1", "icp_slam.alfa: must be <= 0.99, got 1");
  refused(laser, "icp_slam.smallest_threshold_dist=1",
          "icp_slam.smallest_threshold_dist: must be <= threshold_dist (0.3), got 1");
  const std::string point = test::source_path("scenarios/s-f8.json").string();
  refused(point, "batch_optimum.start_sigma_position=1e300", "batch_optimum.start_sigma_position: must be <= 1e+06");
  refused(point, "batch_optimum.start_sigma_rotation_deg=200",
          "batch_optimum.start_sigma_rotation_deg: must be <= 180, got 200");
}

}  // namespace
}  // namespace relslam
