// The simulated range sensors' rawlogs (scan_rawlog.hpp) as MRPT reads them: a laser run written
// by `relslam simulate`'s source and a depth frame, read back with MRPT's CRawlog.
#include "test_support.hpp"

#include "relslam/eval/io/scan_rawlog.hpp"
#include "relslam/eval/sources/planar_simulation_source.hpp"
#include "relslam/sim/planar_simulator.hpp"

#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CRawlog.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace relslam::eval {
namespace {

LoadedScenario laser_scenario(const std::string& extra = "") {
  return parse_scenario(R"({"kind": "planar", "seed": 3, "planar": {"map": "d_office_loop", "sensor": "laser",
      "iterations": 40, "speed_scale": 4)" + extra + R"(}, "algorithms": ["icp_slam"]})",
                        "laser.json");
}

TEST(ScanRawlog, SimulatedLaserRunReadBackByMrpt) {
  const test::ScratchDir scratch;
  const std::filesystem::path& dir = scratch.path();
  PlanarSimulationSource source(laser_scenario());
  source.record_into(dir);
  std::vector<PlaneFrame> frames;
  source.stream([&](const PlaneFrame& f, const PlaneTruthFrame&, const std::vector<CsvField>&) { frames.push_back(f); });
  ASSERT_EQ(frames.size(), 40u);

  mrpt::obs::CRawlog log;
  ASSERT_TRUE(log.loadFromRawLogFile((dir / "laser.rawlog").string()));
  ASSERT_EQ(log.size(), 80u);  // action, sensory frame, per scan
  for (std::size_t k = 0; k < frames.size(); ++k) {
    ASSERT_EQ(log.getType(2 * k), mrpt::obs::CRawlog::etActionCollection);
    const auto actions = log.getAsAction(2 * k);
    const auto scan = log.getAsObservations(2 * k + 1)->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
    ASSERT_TRUE(scan);
    const LaserScan& ours = *frames[k].scan;
    ASSERT_EQ(scan->getScanSize(), ours.size());
    EXPECT_NEAR(scan->aperture, std::numbers::pi, 1e-6);
    EXPECT_TRUE(scan->rightToLeft);
    for (std::size_t i = 0; i < ours.size(); ++i) {
      ASSERT_EQ(scan->getScanRangeValidity(i), ours.valid[i] != 0);
      ASSERT_EQ(scan->getScanRange(i), ours.ranges[i]);
    }
    // Odometry: none before the first scan, then the frame's.
    const auto move = actions->getBestMovementEstimation();
    ASSERT_EQ(move != nullptr, k > 0);
    if (k == 0) continue;
    const mrpt::poses::CPose2D m = move->poseChange->getMeanVal();
    EXPECT_NEAR(m.x(), frames[k].odometry->translation.x(), 1e-12);
    EXPECT_NEAR(m.y(), frames[k].odometry->translation.y(), 1e-12);
    EXPECT_NEAR(m.phi(), frames[k].odometry->heading, 1e-12);
  }
}

TEST(ScanRawlog, SameSeedSameScansAndBytes) {
  const test::ScratchDir scratch_a, scratch_b;
  const std::filesystem::path a = scratch_a.path(), b = scratch_b.path();
  for (const auto& dir : {a, b}) {
    PlanarSimulationSource source(laser_scenario());
    source.record_into(dir);
    source.stream([](const PlaneFrame&, const PlaneTruthFrame&, const std::vector<CsvField>&) {});
  }
  EXPECT_EQ(test::read_file(a / "laser.rawlog"), test::read_file(b / "laser.rawlog"));
}

TEST(ScanRawlog, DepthFrameReadBackByMrpt) {
  const test::ScratchDir scratch;
  const std::filesystem::path& dir = scratch.path();
  sim::PlanarWorld world;
  world.walls = {sim::Wall::between(0, {3, -5}, {3, 5})};
  sim::DepthCameraOptions camera;
  camera.noise_per_depth2 = 0;
  camera.missing = 0;
  const sim::DepthFrame frame = sim::DepthCamera(camera).frame(world, PlanarPose::from(0, 0, 0), 1, 0);
  {
    ScanRawlogWriter writer(dir / "depth.rawlog", false);
    writer.write(frame, camera, std::nullopt, 1.0e9);
    writer.close();
  }
  mrpt::obs::CRawlog log;
  ASSERT_TRUE(log.loadFromRawLogFile((dir / "depth.rawlog").string()));
  ASSERT_EQ(log.size(), 2u);
  const auto obs = log.getAsObservations(1)->getObservationByClass<mrpt::obs::CObservation3DRangeScan>();
  ASSERT_TRUE(obs);
  ASSERT_TRUE(obs->hasRangeImage);
  ASSERT_EQ(obs->rangeImage.cols(), 640);
  ASSERT_EQ(obs->rangeImage.rows(), 480);
  EXPECT_DOUBLE_EQ(obs->cameraParams.fx(), 525.0);
  // The wall 3 ahead at depth 3000 mm on the image's centre rows; the floor below at 1/y_c.
  EXPECT_EQ(obs->rangeImage(240, 320), 3000);
  EXPECT_EQ(obs->rangeImage(479, 320), static_cast<std::uint16_t>(std::round(1000.0 / ((479 - 239.5) / 525.0))));
}

}  // namespace
}  // namespace relslam::eval
