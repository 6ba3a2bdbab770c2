#include "relslam/sim/depth_camera.hpp"

#include "checked.hpp"
#include "relslam/sim/random.hpp"
#include "relslam/sim/ray_cast.hpp"

#include <cmath>
#include <limits>

namespace relslam::sim {

std::vector<OptionIssue> check(const DepthCameraOptions& options) { return check_fields(options); }

DepthCamera::DepthCamera(const DepthCameraOptions& options) : options_(checked(options)) {}

// Pixel (u, v) looks along (x_c, y_c, 1) in the camera frame, x_c = (u − cx)/fx, y_c = (v − cy)/fy
// (y down). Its horizontal part is (x_c, 1) for every v, so one floor-plan ray per column serves
// all its pixels: at depth z the ray has gone z·√(1 + x_c²) across the floor and stands
// camera_height − y_c·z above it.
void DepthCamera::cast_column(const PlanarWorld& world, const PlanarPose& world_T_robot, int u, DepthFrame& out) const {
  const DepthCameraOptions& o = options_;
  const double x_c = (u - o.cx) / o.fx;
  const double stretch = std::sqrt(1.0 + x_c * x_c);  // floor distance per unit of depth
  // Image x runs to the robot's right, that is towards −z of the planar frame.
  const double angle = world_T_robot.heading - std::atan(x_c);
  const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
  const std::vector<RayHit> hits = ray_hits(world, world_T_robot.translation, direction, o.max_depth * stretch);
  for (int v = 0; v < o.height; ++v) {
    const double y_c = (v - o.cy) / o.fy;
    // The floor (y_c > 0) or the ceiling (y_c < 0) bounds the ray; level rays meet neither.
    double depth = std::numeric_limits<double>::infinity();
    int truth = kDepthNothing;
    if (y_c > 0) depth = o.camera_height / y_c, truth = kDepthFloor;
    if (y_c < 0) depth = (o.camera_height - o.ceiling_height) / y_c, truth = kDepthCeiling;
    for (const RayHit& hit : hits) {
      const double z = hit.distance / stretch;
      if (z >= depth) break;
      const double up = o.camera_height - y_c * z;
      const Wall& wall = world.walls[static_cast<std::size_t>(hit.wall)];
      if (up >= 0.0 && up <= wall.height) {
        depth = z, truth = wall.id;
        break;
      }
    }
    const std::size_t i = static_cast<std::size_t>(v) * o.width + u;
    out.truth[i] = truth;
    out.depth[i] = depth <= o.max_depth ? static_cast<float>(depth) : 0.0f;
    if (depth > o.max_depth) out.truth[i] = kDepthNothing;
  }
}

DepthFrame DepthCamera::frame(const PlanarWorld& world, const PlanarPose& world_T_robot, std::uint64_t seed,
                              int k) const {
  const DepthCameraOptions& o = options_;
  DepthFrame out;
  out.width = o.width;
  out.height = o.height;
  out.depth.assign(static_cast<std::size_t>(o.width) * o.height, 0.0f);
  out.truth.assign(out.depth.size(), kDepthNothing);
  for (int u = 0; u < o.width; ++u) {
    cast_column(world, world_T_robot, u, out);
    // Two draws per pixel, whether used or not, from a stream of this column: the noise of a
    // pixel does not depend on what the others see.
    RandomSequence rng(seed, Stream::DepthPixel, static_cast<std::uint64_t>(k), static_cast<std::uint64_t>(u));
    for (int v = 0; v < o.height; ++v) {
      float& d = out.depth[static_cast<std::size_t>(v) * o.width + u];
      const double error = rng.gaussian() * o.noise_per_depth2 * d * d;
      const bool dropped = rng.uniform() < o.missing;
      if (d == 0.0f) continue;
      const double noisy = d + error;
      d = dropped || noisy < o.min_depth || noisy > o.max_depth ? 0.0f : static_cast<float>(noisy);
    }
  }
  return out;
}

std::vector<Eigen::Vector3d> depth_points(const DepthFrame& frame, const DepthCameraOptions& o) {
  std::vector<Eigen::Vector3d> points(frame.depth.size(), Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()));
  for (int v = 0; v < frame.height; ++v)
    for (int u = 0; u < frame.width; ++u) {
      const double z = frame.at(u, v);
      if (z <= 0.0) continue;
      // Image x runs to the robot's right (−z), image y down (−y).
      points[static_cast<std::size_t>(v) * frame.width + u] = {z, -(v - o.cy) / o.fy * z, -(u - o.cx) / o.fx * z};
    }
  return points;
}

}  // namespace relslam::sim
