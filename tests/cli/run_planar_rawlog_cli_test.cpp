// relslam run --rawlog on planar (2D range-bearing) logs: recognised by the source,
// run through the planar machinery (relative_point + ekf2d, Relative Point bridged by the
// log's odometry), and a Relative Point run whose pose is lost for most of it says so.
#include "relslam/eval/io/range_bearing.hpp"
#include "relslam/eval/io/rawlog.hpp"
#include "relslam/eval/metrics/summary_reader.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <random>

namespace relslam {
namespace {

using test::CsvTable;
using test::read_csv;
using test::run_relslam;

// A world like MRPT's kf-slam demo (simul_landmarks_demo_EKF-SLAM.ini): a robot drives a square
// in 0.2 m steps and turns its corners 22.5 degrees a frame in place, seeing about 70 landmarks
// within 6 m over 180 degrees, range-bearing noise of centimetres.
struct DemoWorld {
  bool odometry = true;        // 2D odometry actions before every frame
  double height_spread = 0.0;  // > 0: landmarks up to this far above and below the plane (a 3D log)
  int frames = 250;
};

struct Rng {
  std::mt19937 engine{35};
  double uniform() { return static_cast<double>(engine()) / 4294967296.0; }  // the same on every platform
  double noise(double sigma) { return (uniform() + uniform() + uniform() - 1.5) * 2.0 * sigma; }
};

std::vector<eval::Pose2> square_path(int frames) {
  std::vector<eval::Pose2> path(1);
  while (static_cast<int>(path.size()) < frames) {
    eval::Pose2 p = path.back();
    const int k = static_cast<int>(path.size() - 1) % 44;  // 40 steps ahead, 4 turning
    if (k < 40) {
      p.x += 0.2 * std::cos(p.heading);
      p.y += 0.2 * std::sin(p.heading);
    } else {
      p.heading += std::numbers::pi / 8;
    }
    path.push_back(p);
  }
  return path;
}

// Writes dir/log.rawlog with dir/path.txt and dir/landmarks.txt in MRPT's truth formats.
void write_demo_world(const std::filesystem::path& dir, const DemoWorld& world) {
  Rng rng;
  std::vector<Eigen::Vector3d> landmarks;  // MRPT world axes; a jittered 2 m grid around the square
  for (double x = -3; x <= 11; x += 2)
    for (double y = -2; y <= 11; y += 2)
      landmarks.push_back({x + rng.noise(0.5), y + rng.noise(0.5), world.height_spread * (2 * rng.uniform() - 1)});
  std::ofstream truth_landmarks(dir / "landmarks.txt");
  truth_landmarks.precision(17);
  for (std::size_t i = 0; i < landmarks.size(); ++i)
    truth_landmarks << landmarks[i].x() << ' ' << landmarks[i].y() << ' ' << landmarks[i].z() << " 0 0 0 " << i + 1
                    << '\n';
  const eval::RangeBearingSensor sensor{0.0, 6.0, std::numbers::pi, 0.0, 0.01, 0.1 * std::numbers::pi / 180, 0.0};
  eval::RawlogWriter log(dir / "log.rawlog", sensor, false);
  std::ofstream truth_path(dir / "path.txt");
  truth_path.precision(17);
  const std::vector<eval::Pose2> path = square_path(world.frames);
  for (std::size_t k = 0; k < path.size(); ++k) {
    const eval::Pose2& p = path[k];
    truth_path << p.x << ' ' << p.y << " 0 " << p.heading << " 0 0\n";
    ObservationFrame frame;
    frame.iteration = static_cast<int>(k);
    std::vector<int> ids;
    const double c = std::cos(p.heading), s = std::sin(p.heading);
    for (std::size_t i = 0; i < landmarks.size(); ++i) {
      const double dx = landmarks[i].x() - p.x, dy = landmarks[i].y() - p.y;
      const Eigen::Vector3d local(c * dx + s * dy, -s * dx + c * dy, landmarks[i].z());
      if (local.x() <= 0 || local.norm() > 6.0) continue;
      frame.points.push_back(eval::robot_from_mrpt(local + Eigen::Vector3d(rng.noise(0.01), rng.noise(0.01), 0)));
      ids.push_back(static_cast<int>(i + 1));
    }
    if (world.odometry && k > 0) {
      const eval::Pose2& q = path[k - 1];
      const double qc = std::cos(q.heading), qs = std::sin(q.heading);
      const double mx = p.x - q.x, my = p.y - q.y;
      frame.odometry =
          eval::robot_pose_from_planar({qc * mx + qs * my + rng.noise(0.02), -qs * mx + qc * my + rng.noise(0.02),
                                        p.heading - q.heading + rng.noise(0.005)});
    }
    log.write(frame, ids, eval::kSimulationEpoch_s + static_cast<double>(k));
  }
  log.close();
}

std::vector<std::string> run_args(const std::filesystem::path& log, const std::filesystem::path& truth_path,
                                  const std::filesystem::path& truth_landmarks, const std::filesystem::path& out) {
  return {"run",
          "--rawlog",
          log.string(),
          "--truth-path",
          truth_path.string(),
          "--truth-landmarks",
          truth_landmarks.string(),
          "--out",
          out.string(),
          "-q"};
}

// Relative Point and ekf2d both finished, Relative Point's ATE within twice the EKF's.
void expect_planar_run(const std::filesystem::path& out) {
  const CsvTable summary = read_csv(out / "summary.csv");
  ASSERT_EQ(summary.rows.size(), 3u);  // relative_point, ekf2d, their ratio
  EXPECT_EQ(summary.text(0, "algorithm"), "relative_point");
  EXPECT_EQ(summary.text(1, "algorithm"), "ekf2d");
  EXPECT_EQ(summary.text(0, "status"), "ok");
  EXPECT_EQ(summary.text(1, "status"), "ok");
  EXPECT_LE(summary.number(0, "ate_rmse"), 2 * summary.number(1, "ate_rmse"))
      << "relative_point " << summary.number(0, "ate_rmse") << " ekf2d " << summary.number(1, "ate_rmse");
  const std::string manifest = test::read_file(out / "manifest.json");
  EXPECT_NE(manifest.find("\"planar\": true"), std::string::npos);
}

TEST(PlanarRawlog, MrptsTwoDimensionalDemoRunsThroughThePlanarMachinery) {
  const std::filesystem::path data = "/usr/share/mrpt/datasets";
  if (!std::filesystem::exists(data / "kf-slam_demo.rawlog"))
    GTEST_SKIP() << "no " << (data / "kf-slam_demo.rawlog") << " (package mrpt-common): nothing to run";
  test::ScratchDir dir;
  const auto r = run_relslam(run_args(data / "kf-slam_demo.rawlog", data / "kf-slam_demo_ground_truth_robot_path.txt",
                                      data / "kf-slam_demo_ground_truth.txt", dir / "run"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_planar_run(dir / "run");
}

TEST(PlanarRawlog, AGeneratedTwoDimensionalLogRunsThroughThePlanarMachinery) {
  test::ScratchDir dir;
  write_demo_world(dir.path(), {});
  const auto r = run_relslam(run_args(dir / "log.rawlog", dir / "path.txt", dir / "landmarks.txt", dir / "run"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_planar_run(dir / "run");
}

TEST(PlanarRawlog, APoseFromUnmappedPointsForMostOfTheRunIsLost) {
  // Without odometry nothing bridges the corners: a point 6 m away moves 2.4 m in a turning
  // frame, its neighbours are about 2 m apart, and Relative Point stops mapping.
  test::ScratchDir dir;
  write_demo_world(dir.path(), {.odometry = false});
  const auto r = run_relslam(run_args(dir / "log.rawlog", dir / "path.txt", dir / "landmarks.txt", dir / "run"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<eval::SummaryRow> rows = eval::read_summary(dir / "run" / "summary.csv");
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows[0].algorithm, "relative_point");
  EXPECT_EQ(rows[0].status.kind, eval::RunStatus::Kind::Lost) << rows[0].status.text();
  EXPECT_EQ(rows[0].status.text().rfind("lost: pose from ", 0), 0u) << rows[0].status.text();
}

// The planar EKF on the same log without odometry cannot follow the turns either: its update
// throws its pose off the path, and the divergence check records it (with odometry, above, ok).
TEST(PlanarRawlog, AnEkfThatLosesThePathIsLostNotOk) {
  test::ScratchDir dir;
  write_demo_world(dir.path(), {.odometry = false});
  const auto r = run_relslam(run_args(dir / "log.rawlog", dir / "path.txt", dir / "landmarks.txt", dir / "run"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<eval::SummaryRow> rows = eval::read_summary(dir / "run" / "summary.csv");
  ASSERT_GE(rows.size(), 2u);
  EXPECT_EQ(rows[1].algorithm, "ekf2d");
  EXPECT_EQ(rows[1].status.kind, eval::RunStatus::Kind::Lost) << rows[1].status.text();
  EXPECT_EQ(rows[1].status.text().rfind("lost: diverged at iteration ", 0), 0u) << rows[1].status.text();
  EXPECT_GT(rows[1].trajectory.ate_rmse, 1.0);  // it is off indeed
}

TEST(PlanarRawlog, TheTwoDimensionalEkfIsRefusedOnAThreeDimensionalLog) {
  test::ScratchDir dir;
  write_demo_world(dir.path(), {.height_spread = 1.0, .frames = 60});
  auto args = run_args(dir / "log.rawlog", dir / "path.txt", dir / "landmarks.txt", dir / "run");
  args.insert(args.end(), {"--set", "algorithms=relative_point,ekf2d"});
  const auto refused = run_relslam(args);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("not planar"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("use ekf6d"), std::string::npos) << refused.err;
  // Without a scenario a 3D log gets the 6D EKF.
  const auto r = run_relslam(run_args(dir / "log.rawlog", dir / "path.txt", dir / "landmarks.txt", dir / "default"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_csv(dir / "default" / "summary.csv").text(1, "algorithm"), "ekf6d");
}

}  // namespace
}  // namespace relslam
