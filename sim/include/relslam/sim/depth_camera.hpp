#pragma once
// A simulated depth camera over the planar world with a floor and a ceiling: a Kinect-like
// 640×480 depth image with per-pixel truth, so plane extraction (thesis Chapter 5, EM) can be
// scored on sensor-sized frames. The camera looks along the robot's heading with its optical
// axis level; every image column is one horizontal ray of the shared ray caster
// (ray_cast.hpp), and each pixel of the column takes the first of that ray's walls within the
// wall's height, or else the floor or the ceiling. Part of relslam/sim: Eigen only.

#include "relslam/core/option_fields.hpp"
#include "relslam/core/option_issue.hpp"
#include "relslam/core/planar_pose.hpp"
#include "relslam/sim/planar_world.hpp"

#include <cstdint>
#include <vector>

namespace relslam::sim {

// Tags: [C] chosen here; "Kinect" values are the Kinect v1's commonly used calibration and
// error model (Khoshelham & Elberink 2012, "Accuracy and resolution of Kinect depth data":
// random error σ_z ≈ 1.425e-3 · z² m).
struct DepthCameraOptions {
  int width = 640;            // pixels [C Kinect]
  int height = 480;           // pixels [C Kinect]
  double fx = 525.0;          // focal lengths, pixels [C Kinect]
  double fy = 525.0;
  double cx = 319.5;          // principal point, pixels [C Kinect]
  double cy = 239.5;
  double camera_height = 1.0;   // optical centre above the floor, map units [C]
  double ceiling_height = 2.5;  // the ceiling above the floor; the walls' default height [C]
  double min_depth = 0.5;       // nearer returns are missing [C Kinect]
  double max_depth = 8.0;       // farther returns are missing [C Kinect]
  double noise_per_depth2 = 1.425e-3;  // σ of the depth = this · depth², per map unit (0: none) [C Kinect]
  double missing = 0.02;               // probability that a pixel in range has no return [C]
};

void describe(OptionsOf<DepthCameraOptions> auto& o, auto& f) {
  f.field("width", o.width, "image width, pixels", at_least(1), at_most(8192));
  f.field("height", o.height, "image height, pixels", at_least(1), at_most(8192));
  f.field("fx", o.fx, "horizontal focal length, pixels", above(0.0));
  f.field("fy", o.fy, "vertical focal length, pixels", above(0.0));
  f.field("cx", o.cx, "principal point column, pixels");
  f.field("cy", o.cy, "principal point row, pixels");
  f.field("camera_height", o.camera_height, "optical centre above the floor, map units", above(0.0),
          holds(o.camera_height < o.ceiling_height, "must be below ceiling_height"));
  f.field("ceiling_height", o.ceiling_height, "ceiling above the floor, map units", above(0.0), at_most(1e6));
  f.field("min_depth", o.min_depth, "nearer returns are missing, map units", at_least(0.0));
  f.field("max_depth", o.max_depth, "farther returns are missing, map units", above(o.min_depth, "min_depth"),
          at_most(1e6));
  f.field("noise_per_depth2", o.noise_per_depth2, "depth noise sigma per depth squared (0: none)", at_least(0.0),
          at_most(1.0));
  f.field("missing", o.missing, "probability that a pixel in range has no return", at_least(0.0), at_most(1.0));
}

std::vector<OptionIssue> check(const DepthCameraOptions& options);

// What a pixel sees, the truth beside the depth: a wall (its id, >= 0) or one of these.
inline constexpr int kDepthNothing = -1;  // no surface within max_depth
inline constexpr int kDepthFloor = -2;
inline constexpr int kDepthCeiling = -3;

// Row-major images, pixel (u, v) at v * width + u; image x to the right, y down, depth along
// the optical axis (the robot's heading), as a Kinect reports it.
struct DepthFrame {
  int width = 0;
  int height = 0;
  std::vector<float> depth;  // map units; 0 where there is no return
  std::vector<int> truth;    // the surface each ray meets (wall id, kDepthFloor, ...), also where depth is 0
  float at(int u, int v) const { return depth[static_cast<std::size_t>(v) * width + u]; }
  int truth_at(int u, int v) const { return truth[static_cast<std::size_t>(v) * width + u]; }
};

// The frame's returns as 3-D points in the planar robot frame (x forward along the optical axis,
// y up from the camera, z to the robot's left; see the planar half in docs/frames.md), row-major
// like the image (an organised cloud), NaN where there is no return. The camera is the origin,
// as EM's planes expect (their normals face the sensor).
std::vector<Eigen::Vector3d> depth_points(const DepthFrame& frame, const DepthCameraOptions& options);

class DepthCamera {
 public:
  // Throws OptionError when the options fail check().
  explicit DepthCamera(const DepthCameraOptions& options);
  const DepthCameraOptions& options() const { return options_; }

  // The image at iteration k from world_T_robot (the camera at the robot's origin, looking
  // along its heading): a pure function of (world, options, seed, k).
  DepthFrame frame(const PlanarWorld& world, const PlanarPose& world_T_robot, std::uint64_t seed, int k) const;

 private:
  // Column u's depths and truth, noise-free.
  void cast_column(const PlanarWorld& world, const PlanarPose& world_T_robot, int u, DepthFrame& out) const;
  DepthCameraOptions options_;
};

}  // namespace relslam::sim
