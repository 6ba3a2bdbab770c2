// Pictures and comparisons of any run folder from its files: relslam render --overview (the
// default for runs that cannot be replayed) and relslam compare, on a rawlog run, a planar run
// and a sweep's cell, and a clear refusal for a damaged folder.

#include "test_support.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace relslam {
namespace {

namespace fs = std::filesystem;
using test::run_relslam;

std::string scenario(const std::string& name) { return test::source_path("scenarios/" + name).string(); }

// A short figure eight with both algorithms, and the same observations replayed from its rawlog.
void make_runs(const fs::path& dir) {
  ASSERT_EQ(run_relslam({"run", scenario("s-ekf-f8.json"), "--out", (dir / "sim").string(), "-q", "--set",
                         "sim.iterations=120", "--set", "output.observations_csv=false"})
                .exit_code,
            0);
  ASSERT_EQ(run_relslam(
                {"run", "--out", (dir / "log").string(), "-q", "--rawlog", (dir / "sim/observations.rawlog").string()})
                .exit_code,
            0);
}

// A picture the size asked for with more than the background in it.
void expect_picture(const fs::path& file) {
  const cv::Mat image = cv::imread(file.string());
  ASSERT_FALSE(image.empty()) << file;
  EXPECT_EQ(image.cols, 1280);
  cv::Mat grey;
  cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  EXPECT_GT(image.total() - static_cast<std::size_t>(cv::countNonZero(grey == 255)), 1000u) << file << " is blank";
}

TEST(RenderOverview, ARawlogRunIsDrawnFromItsFilesByDefault) {
  test::ScratchDir dir;
  make_runs(dir.path());
  const auto r = run_relslam({"render", (dir / "log").string(), "--out", (dir / "log.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_picture(dir / "log.png");
  const auto replay = run_relslam({"render", (dir / "log").string(), "--iteration", "10", "--out", "x.png"});
  EXPECT_EQ(replay.exit_code, 2);
  EXPECT_NE(replay.err.find("--overview"), std::string::npos) << replay.err;
}

TEST(RenderOverview, PlanarRunsAndSweepCellsToo) {
  test::ScratchDir dir;
  ASSERT_EQ(run_relslam({"run", scenario("p-hallway.json"), "--out", (dir / "planar").string(), "-q"}).exit_code, 0);
  ASSERT_EQ(
      run_relslam({"render", (dir / "planar").string(), "--overview", "--out", (dir / "p.png").string()}).exit_code, 0);
  expect_picture(dir / "p.png");
  ASSERT_EQ(run_relslam({"sweep", scenario("s-f8.json"), "--out", (dir / "sweep").string(), "-q", "--seeds", "2",
                         "--set", "sim.iterations=60"})
                .exit_code,
            0);
  ASSERT_EQ(run_relslam({"render", (dir / "sweep/seed-2").string(), "--overview", "--out", (dir / "c.png").string()})
                .exit_code,
            0);
  expect_picture(dir / "c.png");
}

TEST(RenderOverview, ADamagedTrajectoryIsRefusedWithItsLine) {
  test::ScratchDir dir;
  make_runs(dir.path());
  test::write_file(dir / "log/relative_point/trajectory.tum", "0 0 0 0 0 0 0 1\n1 2 3\n");
  const auto r = run_relslam({"render", (dir / "log").string(), "--out", (dir / "x.png").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("relative_point/trajectory.tum:2:"), std::string::npos) << r.err;
}

TEST(CompareCommand, SetsTwoRunsSideBySideWithDifferencesAndOnePicture) {
  test::ScratchDir dir;
  make_runs(dir.path());
  const auto r =
      run_relslam({"compare", (dir / "sim").string(), (dir / "log").string(), "--out", (dir / "both.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* part : {"relative_point   A: ok   B: ok", "ekf6d   A: ok   B: ok", "final mean landmark error",
                           "B - A", "B / A", "median time per iteration (ms)"})
    EXPECT_NE(r.out.find(part), std::string::npos) << part << " in:\n" << r.out;
  expect_picture(dir / "both.png");
  fs::remove(dir / "log/summary.csv");
  const auto damaged = run_relslam({"compare", (dir / "sim").string(), (dir / "log").string()});
  EXPECT_EQ(damaged.exit_code, 2);
  EXPECT_NE(damaged.err.find("summary.csv: not found"), std::string::npos) << damaged.err;
}

}  // namespace
}  // namespace relslam
