#pragma once
// Frames of the simulated depth camera (sim/depth_camera.hpp) with what scoring needs: the
// organised cloud EM takes, each pixel's true surface (a wall, the floor, the ceiling), each
// surface's true normal (fit on the noise-free image: exact, as the surfaces are planes) and its
// area in view. Shared by the EM tests and the cloud benchmark.

#include "depth_scenes.hpp"
#include "relslam/em/em_plane.hpp"
#include "relslam/sim/depth_camera.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace relslam::em::test {

struct SimDepthView {
  std::vector<Eigen::Vector3d> points;  // sim::depth_points of the noisy frame
  int width = 0, height = 0;
  std::vector<int> surface;                   // per pixel: index into the lists below, -1 for none
  std::vector<int> ids;                       // per surface: the wall id, kDepthFloor or kDepthCeiling
  std::vector<Eigen::Vector3d> true_normals;  // per surface, planar robot frame
  std::vector<double> area;                   // per surface: square map units in view (its returns)
};

// A 6 × 5 room (walls 10–13, facing in) with a 0.8 × 0.8 pillar (walls 20–23, facing out), the
// size a Kinect sees well, and six poses in it looking every way.
sim::PlanarWorld pillar_room();
std::vector<PlanarPose> pillar_room_poses();

// Frame k at world_T_robot by a camera with `options` (noise and missing returns as they say).
SimDepthView sim_depth_view(const sim::PlanarWorld& world, const sim::DepthCameraOptions& options,
                            const PlanarPose& world_T_robot, std::uint64_t seed, int k);

// Recall, precision and normal error of `planes` (over the view's pixel indices); recall counts
// the surfaces with at least `min_area` in view.
DepthScore score_view(const SimDepthView& view, const std::vector<EmPlane>& planes, double min_area);

}  // namespace relslam::em::test
