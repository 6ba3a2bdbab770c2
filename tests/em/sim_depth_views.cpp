#include "sim_depth_views.hpp"

#include "relslam/em/tls_fit.hpp"

#include <algorithm>
#include <cmath>

namespace relslam::em::test {

// σ = 1.425e-3 · z² of a Kinect is 2 cm at 3.7 m, across this room.
sim::PlanarWorld pillar_room() {
  using sim::Wall;
  sim::PlanarWorld w;
  w.walls = {Wall::between(10, {-3, -2.5}, {3, -2.5}),     Wall::between(11, {3, -2.5}, {3, 2.5}),
             Wall::between(12, {3, 2.5}, {-3, 2.5}),       Wall::between(13, {-3, 2.5}, {-3, -2.5}),
             Wall::between(20, {1.0, -0.2}, {1.0, 0.6}),   Wall::between(21, {1.8, -0.2}, {1.0, -0.2}),
             Wall::between(22, {1.8, 0.6}, {1.8, -0.2}),   Wall::between(23, {1.0, 0.6}, {1.8, 0.6})};
  return w;
}

std::vector<PlanarPose> pillar_room_poses() {
  return {PlanarPose::from(-2.0, 0.0, 0.0), PlanarPose::from(-1.5, -1.5, 0.6), PlanarPose::from(0.0, 1.5, -0.4),
          PlanarPose::from(2.0, -1.5, 1.9), PlanarPose::from(-1.0, 0.5, 3.0),  PlanarPose::from(0.5, -1.0, -1.2)};
}

SimDepthView sim_depth_view(const sim::PlanarWorld& world, const sim::DepthCameraOptions& options,
                            const PlanarPose& world_T_robot, std::uint64_t seed, int k) {
  sim::DepthCameraOptions exact = options;
  exact.noise_per_depth2 = 0.0;
  exact.missing = 0.0;
  const sim::DepthFrame noisy = sim::DepthCamera(options).frame(world, world_T_robot, seed, k);
  const sim::DepthFrame clean = sim::DepthCamera(exact).frame(world, world_T_robot, seed, k);
  const std::vector<Eigen::Vector3d> clean_points = sim::depth_points(clean, options);
  SimDepthView v;
  v.points = sim::depth_points(noisy, options);
  v.width = noisy.width, v.height = noisy.height;
  v.surface.assign(noisy.truth.size(), -1);
  std::vector<std::vector<int>> pixels;
  for (std::size_t i = 0; i < noisy.truth.size(); ++i) {
    if (noisy.truth[i] == sim::kDepthNothing || clean.depth[i] <= 0.0f) continue;
    const auto at = std::find(v.ids.begin(), v.ids.end(), noisy.truth[i]);
    if (at == v.ids.end()) v.ids.push_back(noisy.truth[i]), pixels.emplace_back();
    const auto s = static_cast<std::size_t>(std::find(v.ids.begin(), v.ids.end(), noisy.truth[i]) - v.ids.begin());
    pixels[s].push_back(static_cast<int>(i));
    if (noisy.depth[i] > 0.0f) v.surface[i] = static_cast<int>(s);
  }
  for (std::size_t s = 0; s < v.ids.size(); ++s) {
    const std::optional<PlaneFit> fit = fit_plane(clean_points, pixels[s]);
    v.true_normals.push_back(fit ? fit->normal : Eigen::Vector3d::Zero());
    // A pixel whose ray makes an angle with cosine c to the optical axis spans c³ / (fx · fy)
    // steradians; at depth z (range z / c), seen at incidence cosine i: z² · c / (fx · fy · i).
    double area = 0.0;
    for (int i : pixels[s]) {
      if (noisy.depth[static_cast<std::size_t>(i)] <= 0.0f) continue;
      const Eigen::Vector3d& p = clean_points[static_cast<std::size_t>(i)];
      const double r = p.norm(), c = p.x() / r, incidence = std::abs(v.true_normals[s].dot(p)) / r;
      if (incidence > 1e-3) area += p.x() * p.x() * c / (options.fx * options.fy * incidence);
    }
    v.area.push_back(area);
  }
  return v;
}

DepthScore score_view(const SimDepthView& view, const std::vector<EmPlane>& planes, double min_area) {
  std::vector<bool> required;
  for (double a : view.area) required.push_back(a >= min_area);
  std::vector<std::vector<int>> supports;
  std::vector<Eigen::Vector3d> normals;
  for (const EmPlane& p : planes) supports.push_back(p.points), normals.push_back(p.normal);
  return score_surfaces(view.surface, view.true_normals, required, supports, normals);
}

}  // namespace relslam::em::test
