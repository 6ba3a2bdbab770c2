// Plane frames from files (relslam run --planes): a simulated planar run fed back through its
// own files is the same run — the same input digest and the same algorithm files byte for byte
// but for the measured times — with the plane sensor and with EM in the loop; a damaged file is
// refused at its line; without truth nothing is scored as if it were known.

#include "test_support.hpp"

#include "relslam/eval/io/run_overview.hpp"

#include <gtest/gtest.h>

namespace relslam {
namespace {

namespace fs = std::filesystem;
using test::read_csv;
using test::run_relslam;

// A CSV file's text without its timing columns (*_ms) and the simulation's own extraction count
// (a column only a source that extracts planes has), or a TUM file's text.
std::string untimed_text(const fs::path& file) {
  const auto lines = test::read_lines(file);
  if (file.extension() != ".csv" || lines.empty()) return test::read_file(file);
  const test::CsvTable t = read_csv(file);
  std::string text;
  for (const auto& row : t.rows) {
    for (std::size_t c = 0; c < row.size() && c < t.header.size(); ++c)
      if (!t.header[c].ends_with("_ms") && t.header[c] != "extracted_planes") text += row[c] + ",";
    text += "\n";
  }
  return text;
}

void expect_round_trip(const std::string& scenario, const std::string& iterations) {
  test::ScratchDir dir;
  const std::string path = test::source_path("scenarios/" + scenario).string();
  ASSERT_EQ(run_relslam({"run", path, "--out", (dir / "sim").string(), "-q", "--set", iterations}).exit_code, 0);
  const auto r = run_relslam({"run", path, "--out", (dir / "file").string(), "-q", "--set", iterations, "--planes",
                              (dir / "sim/plane_observations.csv").string(), "--truth-path",
                              (dir / "sim/ground_truth_poses.csv").string(), "--truth-walls",
                              (dir / "sim/ground_truth_walls.csv").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_csv(dir / "file/summary.csv").text(0, "input_digest"),
            read_csv(dir / "sim/summary.csv").text(0, "input_digest"));
  int compared = 0;
  for (const auto& entry : fs::directory_iterator(dir / "sim/relative_plane")) {
    const fs::path name = entry.path().filename();
    EXPECT_TRUE(untimed_text(dir / "file/relative_plane" / name) == untimed_text(entry.path()))
        << scenario << ": " << name;
    ++compared;
  }
  EXPECT_GE(compared, 8);
}

TEST(PlaneFile, ASimulatedRunFedBackThroughItsFilesIsTheSameRun) {
  expect_round_trip("p-room.json", "planar.iterations=600");
}

TEST(PlaneFile, TheSameWithEmExtractingThePlanes) { expect_round_trip("p-em-room.json", "planar.iterations=200"); }

TEST(PlaneFile, WithoutTruthNoErrorIsScored) {
  test::ScratchDir dir;
  test::write_file(dir / "planes.csv",
                   "iteration,index,kp1_x,kp1_z,kp2_x,kp2_z\n"
                   "0,0,-3,4,3,4\n0,1,3,4,3,-1\n1,0,-3,3.9,3,3.9\n1,1,3,3.9,3,-1.1\n"
                   "2,0,-3,3.8,3,3.8\n2,1,3,3.8,3,-1.2\n");
  const auto r = run_relslam({"run", "--planes", (dir / "planes.csv").string(), "--out", (dir / "run").string(), "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const test::CsvTable summary = read_csv(dir / "run/summary.csv");
  EXPECT_EQ(summary.text(0, "status"), "ok");
  EXPECT_EQ(summary.text(0, "iterations"), "3");
  for (const char* column : {"final_map_error", "final_position_error", "ate_rmse"})
    EXPECT_EQ(summary.text(0, column), "") << column << ": no truth, no number";
}

// render replays a run by simulating it again; a run whose planes came from a file has nothing
// to simulate, so the replay refuses it (rather than drawing the scenario's default world), and
// the overview draws it from its files: in the planar axes, with the truth it was given.
TEST(PlaneFile, RenderDrawsARunReadFromAFileFromItsFilesOnly) {
  test::ScratchDir dir;
  const std::string path = test::source_path("scenarios/p-room.json").string();
  ASSERT_EQ(run_relslam({"run", path, "--out", (dir / "sim").string(), "-q", "--set", "planar.iterations=100"}).exit_code,
            0);
  ASSERT_EQ(run_relslam({"run", path, "--set", "planar.iterations=100", "--planes",
                         (dir / "sim/plane_observations.csv").string(), "--truth-path",
                         (dir / "sim/ground_truth_poses.csv").string(), "--truth-walls",
                         (dir / "sim/ground_truth_walls.csv").string(), "--out", (dir / "file").string(), "-q"})
                .exit_code,
            0);
  const auto replay = run_relslam({"render", (dir / "file").string(), "--iteration", "50", "--out",
                                   (dir / "pic.png").string()});
  EXPECT_EQ(replay.exit_code, 2);
  EXPECT_NE(replay.err.find("render replays simulated runs"), std::string::npos) << replay.err;
  EXPECT_FALSE(fs::exists(dir / "pic.png"));

  const eval::RunOverview sim = eval::read_run_overview(dir / "sim"), file = eval::read_run_overview(dir / "file");
  EXPECT_TRUE(file.planar);
  ASSERT_EQ(file.true_walls.size(), sim.true_walls.size());
  for (std::size_t i = 0; i < sim.true_walls.size(); ++i)
    EXPECT_LT((file.true_walls[i].first - sim.true_walls[i].first).norm(), 1e-9) << "wall " << i;
  ASSERT_EQ(file.true_path.size(), 100u);
  EXPECT_LT((file.true_path.back() - sim.true_path.back()).norm(), 1e-6);
  ASSERT_EQ(file.tracks.size(), 1u);
  EXPECT_EQ(file.tracks[0].path, sim.tracks[0].path);
}

TEST(PlaneFile, ADamagedFileIsRefusedAtItsLine) {
  test::ScratchDir dir;
  test::write_file(dir / "planes.csv", "iteration,index,kp1_x,kp1_z,kp2_x,kp2_z\n0,0,1,2,3,4\n0,2,1,2,3,4\n");
  const auto r = run_relslam({"run", "--planes", (dir / "planes.csv").string(), "--out", (dir / "run").string(), "-q"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("planes.csv:3: index: expected 1"), std::string::npos) << r.err;
  test::write_file(dir / "back.csv", "iteration,index,kp1_x,kp1_z,kp2_x,kp2_z\n3,0,1,2,3,4\n1,0,1,2,3,4\n");
  const auto back = run_relslam({"run", "--planes", (dir / "back.csv").string(), "--out", (dir / "b").string(), "-q"});
  EXPECT_EQ(back.exit_code, 2);
  EXPECT_NE(back.err.find("back.csv:3: iteration: goes back"), std::string::npos) << back.err;
  const auto point = run_relslam({"run", test::source_path("scenarios/s-f8.json").string(), "--planes",
                                  (dir / "planes.csv").string(), "--out", (dir / "p").string(), "-q"});
  EXPECT_EQ(point.exit_code, 2);
  EXPECT_NE(point.err.find("kind"), std::string::npos) << point.err;
}

}  // namespace
}  // namespace relslam
