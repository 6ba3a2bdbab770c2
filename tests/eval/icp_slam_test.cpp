// MRPT's ICP-SLAM as the planar half's scan-matching baseline (algorithm icp_slam), in process
// on the simulated laser, and the dead-reckoning row (algorithm odometry).
#include "test_support.hpp"

#include "relslam/eval/algorithms/registry.hpp"
#include "relslam/eval/sources/planar_simulation_source.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace relslam::eval {
namespace {

struct PathRun {
  double max_position_error = 0;
  double max_heading_error = 0;
  int frames = 0;
};

// The simulated laser on Map D at 4x speed (0.2 units a step), `iterations` frames through one
// algorithm; its largest pose error against the truth.
PathRun run(const std::string& algorithm, const std::string& planar, const std::string& more = "") {
  const LoadedScenario loaded = parse_scenario(R"({"kind": "planar", "seed": 2, "planar": {"map": "d_office_loop",
      "sensor": "laser", "speed_scale": 4, )" + planar + R"(}, )" + more + R"("algorithms": [")" + algorithm + R"("]})",
                                               "icp.json");
  PlanarSimulationSource source(loaded);
  auto slam = make_plane_algorithm(algorithm, {loaded.scenario, source.start()});
  PathRun out;
  source.stream([&](const PlaneFrame& frame, const PlaneTruthFrame& truth, const std::vector<CsvField>&) {
    slam->step(frame);
    const std::optional<PlanarPose> pose = slam->pose();
    ASSERT_TRUE(pose);
    out.max_position_error = std::max(out.max_position_error, (pose->translation - truth.world_T_robot.translation).norm());
    out.max_heading_error = std::max(out.max_heading_error, std::abs(wrap_angle(pose->heading - truth.world_T_robot.heading)));
    ++out.frames;
  });
  return out;
}

TEST(IcpSlam, NoiseFreeLaserRecoversThePath) {
  // Without odometry (every scan matched from the last pose) and noise-free: the first 150 frames,
  // 30 units of corridor with two corners.
  const PathRun r = run("icp_slam", R"("iterations": 150, "laser": {"range_sigma": 0})",
                        R"("icp_slam": {"use_odometry": false}, )");
  EXPECT_EQ(r.frames, 150);
  // Point-to-point ICP against its sparse point map (every 5th point) still drifts a little:
  // measured 0.11 units and 0.83° at worst over the 30 units.
  EXPECT_LT(r.max_position_error, 0.2);
  EXPECT_LT(r.max_heading_error, 1.5 * std::numbers::pi / 180);
}

TEST(IcpSlam, NoFramesWithoutScansFails) {
  const LoadedScenario loaded = parse_scenario(R"({"kind": "planar", "planar": {"map": "d_office_loop"},
      "algorithms": ["icp_slam"]})", "icp.json");
  auto slam = make_plane_algorithm("icp_slam", {loaded.scenario, PlanarPose()});
  EXPECT_THROW(slam->step(PlaneFrame{}), std::runtime_error);
}

TEST(Odometry, DeadReckoningDriftsWithTheNoiseAndIsExactWithout) {
  const std::string exact = R"("iterations": 150, "odometry": {"translation_ratio": 0, "heading_ratio": 0, "heading_drift_deg": 0})";
  const PathRun clean = run("odometry", exact);
  EXPECT_LT(clean.max_position_error, 1e-9);
  const PathRun noisy = run("odometry", R"("iterations": 150)");
  EXPECT_GT(noisy.max_position_error, 0.05);
}

}  // namespace
}  // namespace relslam::eval
