#include "depth_scenes.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <random>

namespace relslam::em::test {

DepthScene box_room(double yaw_rad, bool pillar) {
  DepthScene s;
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitY()).toRotationMatrix();
  auto plane = [&](Eigen::Vector3d towards_camera, double distance) {
    return TruePlane{turn * towards_camera, distance};
  };
  s.planes = {plane({0, 1, 0}, 1.2),  plane({0, -1, 0}, 1.4), plane({0, 0, -1}, 4.0),
              plane({-1, 0, 0}, 1.8), plane({1, 0, 0}, 2.0)};
  if (pillar) s.planes.push_back(plane({0, 0, -1}, 2.5));
  return s;
}

namespace {

// The pillar face (plane 5) spans x in [-0.2, 0.6] in the room's own axes.
bool inside_pillar(const DepthScene& s, const Eigen::Vector3d& p) {
  const Eigen::Vector3d across = s.planes[3].normal;  // the room's −x
  const double x = -across.dot(p);
  return x >= -0.2 && x <= 0.6;
}

}  // namespace

DepthFrame render(const DepthScene& s, double noise_k, double missing, std::uint64_t seed) {
  DepthFrame f;
  const std::size_t n = static_cast<std::size_t>(s.width) * static_cast<std::size_t>(s.height);
  f.points.assign(n, Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()));
  f.plane_of.assign(n, -1);
  std::mt19937_64 random(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int v = 0; v < s.height; ++v)
    for (int u = 0; u < s.width; ++u) {
      const Eigen::Vector3d ray(-(u - s.cx) / s.fx, -(v - s.cy) / s.fy, 1.0);
      double best = std::numeric_limits<double>::infinity();
      int hit = -1;
      for (std::size_t k = 0; k < s.planes.size(); ++k) {
        const double along = s.planes[k].normal.dot(ray);
        if (!(along < 0)) continue;  // facing away: the camera is on the normal's side
        const double t = -s.planes[k].offset / along;
        if (k == 5 && !inside_pillar(s, t * ray)) continue;
        if (t > 0 && t < best) best = t, hit = static_cast<int>(k);
      }
      const std::size_t i = static_cast<std::size_t>(v) * static_cast<std::size_t>(s.width) + static_cast<std::size_t>(u);
      const double noise = gauss(random), drop = uniform(random);  // drawn for every pixel: stable streams
      if (hit < 0 || drop < missing) continue;
      // Depth noise along the ray (a depth camera measures z): σ = k·z².
      const double z = best;
      f.points[i] = (z + noise_k * z * z * noise) * ray;
      f.plane_of[i] = hit;
    }
  return f;
}

DepthScore score_surfaces(const std::vector<int>& truth, const std::vector<Eigen::Vector3d>& true_normals,
                          const std::vector<bool>& required, const std::vector<std::vector<int>>& supports,
                          const std::vector<Eigen::Vector3d>& normals) {
  DepthScore out;
  for (bool r : required) out.true_planes += r;
  // Largest extracted planes first claim their true plane.
  std::vector<std::size_t> order(supports.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return supports[a].size() > supports[b].size(); });
  std::vector<bool> matched(true_normals.size(), false);
  out.planes = static_cast<int>(supports.size());
  for (std::size_t k : order) {
    std::map<int, int> votes;
    for (int i : supports[k]) ++votes[truth[static_cast<std::size_t>(i)]];
    const auto top = std::max_element(votes.begin(), votes.end(),
                                      [](const auto& a, const auto& b) { return a.second < b.second; });
    if (top == votes.end() || top->first < 0 || 2 * top->second < static_cast<int>(supports[k].size())) continue;
    const auto id = static_cast<std::size_t>(top->first);
    ++out.correct;
    if (matched[id]) {
      ++out.duplicates;
      continue;
    }
    matched[id] = true;
    if (!required[id]) continue;
    ++out.found;
    const double cosine = std::min(1.0, std::abs(normals[k].dot(true_normals[id])));
    out.max_normal_error_deg = std::max(out.max_normal_error_deg, std::acos(cosine) * 180.0 / std::numbers::pi);
  }
  return out;
}

DepthScore score(const DepthScene& scene, const DepthFrame& frame, const std::vector<std::vector<int>>& supports,
                 const std::vector<Eigen::Vector3d>& normals, int min_pixels) {
  std::vector<int> pixels(scene.planes.size(), 0);
  for (int id : frame.plane_of)
    if (id >= 0) ++pixels[static_cast<std::size_t>(id)];
  std::vector<bool> required(scene.planes.size());
  std::vector<Eigen::Vector3d> true_normals;
  for (std::size_t k = 0; k < scene.planes.size(); ++k) {
    required[k] = pixels[k] >= min_pixels;
    true_normals.push_back(scene.planes[k].normal);
  }
  return score_surfaces(frame.plane_of, true_normals, required, supports, normals);
}

}  // namespace relslam::em::test
