// EM2 at sensor density on the simulated depth camera's frames (sim/depth_camera.hpp): a room
// with a pillar seen from several poses, noise-free (every surface found once and exact) and at
// the Kinect's noise and missing returns (recall and precision at least 0.95 over the surfaces
// with at least 0.5 square units in view, normals within a bound).

#include "relslam/em/dense_extraction.hpp"

#include "sim_depth_views.hpp"

#include <gtest/gtest.h>

#include <string>

namespace relslam::em {
namespace {

struct Totals {
  int true_planes = 0, found = 0, planes = 0, correct = 0;
  double max_normal_error_deg = 0;
  std::string log;
};

Totals run(const sim::DepthCameraOptions& camera) {
  Totals t;
  const sim::PlanarWorld world = test::pillar_room();
  int k = 0;
  for (const PlanarPose& pose : test::pillar_room_poses()) {
    const test::SimDepthView view = test::sim_depth_view(world, camera, pose, 5, k++);
    const DenseCloud cloud{view.points, view.width, view.height};
    const DenseResult r = extract_dense(cloud, EmVariant::Em2, EmOptions::for_point_sigma(0.01), DenseOptions{}, 7);
    const test::DepthScore s = test::score_view(view, r.result.planes, 0.5);
    t.true_planes += s.true_planes, t.found += s.found, t.planes += s.planes, t.correct += s.correct;
    t.max_normal_error_deg = std::max(t.max_normal_error_deg, s.max_normal_error_deg);
    t.log += "frame " + std::to_string(k - 1) + ": found " + std::to_string(s.found) + " of " +
             std::to_string(s.true_planes) + ", correct " + std::to_string(s.correct) + " of " +
             std::to_string(s.planes) + ", normal error " + std::to_string(s.max_normal_error_deg) + " deg\n";
  }
  return t;
}

TEST(SimDepthExtraction, NoiseFreeFramesGiveEverySurfaceExact) {
  sim::DepthCameraOptions camera;
  camera.noise_per_depth2 = 0.0;
  camera.missing = 0.0;
  const Totals t = run(camera);
  EXPECT_GE(t.true_planes, 18) << t.log;
  EXPECT_EQ(t.found, t.true_planes) << t.log;
  EXPECT_EQ(t.correct, t.planes) << t.log;
  EXPECT_LT(t.max_normal_error_deg, 0.01) << t.log;
}

TEST(SimDepthExtraction, KinectNoiseRecallAndPrecisionAtLeast95Percent) {
  const Totals t = run(sim::DepthCameraOptions{});  // σ = 1.425e-3 · z², 2 % missing
  EXPECT_GE(t.found, 0.95 * t.true_planes) << t.log;
  EXPECT_GE(t.correct, 0.95 * t.planes) << t.log;
  EXPECT_LT(t.max_normal_error_deg, 1.0) << t.log;
}

}  // namespace
}  // namespace relslam::em
