#pragma once
// Organised test clouds for EM at sensor density: a room of planes (walls, floor, ceiling)
// rendered into a 640 × 480 depth image by a pinhole camera with known intrinsics, with a
// Kinect-like noise that grows with depth² and missing returns, and the true plane of every
// pixel. Shared by the EM tests and the EM benchmark; the simulated depth camera of sim/ is the
// scenario-level sensor, this is the unit-test fixture.

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace relslam::em::test {

struct TruePlane {
  Eigen::Vector3d normal;  // unit, towards the camera
  double offset = 0;       // n·p + d = 0
};

struct DepthScene {
  int width = 640, height = 480;
  double fx = 525, fy = 525, cx = 319.5, cy = 239.5;  // a Kinect's
  std::vector<TruePlane> planes;
};

struct DepthFrame {
  std::vector<Eigen::Vector3d> points;  // row-major, camera = robot frame (+x left, +y up, +z forward); NaN: no return
  std::vector<int> plane_of;            // the true plane per pixel, -1 for no return
};

// A box room around the camera: floor 1.2 below, ceiling 1.4 above, back wall 4 ahead, side
// walls 1.8 left and 2.0 right, all turned by `yaw_rad` about y; with `columns` > 0, a pillar
// face (a wall 0.8 wide, 1.5 ahead of the back wall) in front of it.
DepthScene box_room(double yaw_rad, bool pillar);

// Ray casting: each pixel's nearest plane hit inside the room. `noise_k`: depth noise σ = k·z²
// (Kinect ~0.0012/m); `missing`: the share of pixels without a return. Seeded.
DepthFrame render(const DepthScene& scene, double noise_k, double missing, std::uint64_t seed);

// Recall, precision and normal error of planes (each a list of pixel indices and a normal)
// against the frame's truth: a true plane counts when it has at least `min_pixels` pixels; an
// extracted plane is correct when at least half its pixels are of one true plane, and a
// duplicate when a larger extracted plane is of the same one (a surface split by an occluder
// gives two correct pieces; on a surface seen whole it is over-segmentation). The normal error
// is that of the largest plane of each true plane found.
struct DepthScore {
  int true_planes = 0, found = 0, planes = 0, correct = 0, duplicates = 0;
  double max_normal_error_deg = 0;
  double recall() const { return true_planes ? static_cast<double>(found) / true_planes : 1.0; }
  double precision() const { return planes ? static_cast<double>(correct) / planes : 1.0; }
};
DepthScore score(const DepthScene& scene, const DepthFrame& frame, const std::vector<std::vector<int>>& supports,
                 const std::vector<Eigen::Vector3d>& normals, int min_pixels);

// The same on any frame with per-pixel truth: truth[i] is pixel i's surface (an index into
// `true_normals`, -1 for none), `required` says which surfaces recall counts.
DepthScore score_surfaces(const std::vector<int>& truth, const std::vector<Eigen::Vector3d>& true_normals,
                          const std::vector<bool>& required, const std::vector<std::vector<int>>& supports,
                          const std::vector<Eigen::Vector3d>& normals);

}  // namespace relslam::em::test
