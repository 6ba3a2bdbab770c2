// EM at sensor density on a multi-line lidar's scan (an unorganised cloud whose points lie
// along scan lines: dense along a line, sparse across): a VLP-16-like scan (16 lines 2° apart
// from −15° to +15°, a return every 0.4° along each) of the ground 1.8 below the sensor and two
// walls. Every surface must come out as one plane: on the real VLP-16 scan, before the
// coplanar merge of coplanar_merging.hpp, each line's arc of the ground was a plane of its own,
// and near the sensor's height one line's arc passed for a plane.

#include "relslam/em/dense_extraction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace relslam::em {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// A rectangle of a plane n·p + d = 0 within the axis-aligned bounds lo..hi.
struct Surface {
  Eigen::Vector3d normal;
  double offset;
  Eigen::Vector3d lo, hi;
};

// A yard: the ground 1.8 below the sensor out to 20 each way, a wall 6 to the right (x = −6) and one 14 ahead
// (z = 14), in relslam's axes (+x left, +y up, +z forward).
std::vector<Surface> scene() {
  return {{{0, 1, 0}, 1.8, {-20, -1.8, -20}, {20, -1.8, 20}},
          {{1, 0, 0}, 6.0, {-6, -1.8, -4}, {-6, 1.5, 12}},
          {{0, 0, -1}, 14.0, {-6, -1.8, 14}, {8, 3.0, 14}}};
}

struct Scan {
  std::vector<Eigen::Vector3d> points;
  std::vector<int> surface;  // of each point
};

// Every ray of the scan to its nearest surface; range noise σ (0: none).
Scan lidar_scan(const std::vector<Surface>& surfaces, double sigma, std::uint64_t seed) {
  Scan scan;
  std::mt19937_64 random(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (int line = 0; line < 16; ++line)
    for (int step = 0; step < 900; ++step) {
      const double elevation = (-15.0 + 2.0 * line) * kDegree, azimuth = step * 0.4 * kDegree;
      const Eigen::Vector3d ray(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                                std::cos(elevation) * std::cos(azimuth));
      double nearest = std::numeric_limits<double>::infinity();
      int hit = -1;
      for (std::size_t s = 0; s < surfaces.size(); ++s) {
        const double along = surfaces[s].normal.dot(ray);
        if (std::abs(along) < 1e-9) continue;
        const double t = -surfaces[s].offset / along;
        const Eigen::Vector3d p = t * ray;
        if (t <= 0 || t >= nearest || (p.array() < surfaces[s].lo.array() - 1e-9).any() ||
            (p.array() > surfaces[s].hi.array() + 1e-9).any())
          continue;
        nearest = t, hit = static_cast<int>(s);
      }
      if (hit < 0) continue;
      scan.points.push_back((nearest + sigma * noise(random)) * ray);
      scan.surface.push_back(hit);
    }
  return scan;
}

// Each surface is held (at least 85 % of its points) by one plane, each plane lies (90 %) in
// one surface, one plane per surface, normals within max_error_deg. Measured: the ground 89–90 %
// held; the rest is the outermost line's arcs in the yard's corners, 6 beyond the next line,
// which no seed reaches.
void expect_one_plane_per_surface(double sigma, double max_error_deg) {
  const std::vector<Surface> surfaces = scene();
  const Scan scan = lidar_scan(surfaces, sigma, 3);
  EmOptions o = EmOptions::for_point_sigma(0.1 / 3.0);  // d_in 0.1, as for the VLP-16 scan
  // Seeds reach the next scan line: 1.1 away on the ground at 7 (0.2 · 7 = 1.4).
  o.seed_radius_per_range = 0.2;
  DenseOptions dense;
  dense.summary_points = 20000;
  for (EmVariant v : {EmVariant::Em2}) {
    const std::string name = std::string(v == EmVariant::Em2 ? "em2" : "em1") + " sigma " + std::to_string(sigma);
    const DenseResult r = extract_dense(DenseCloud{scan.points}, v, o, dense, 5);
    std::string found;
    for (const EmPlane& p : r.result.planes)
      found += " n (" + std::to_string(p.normal.x()) + ", " + std::to_string(p.normal.y()) + ", " +
               std::to_string(p.normal.z()) + ") d " + std::to_string(p.offset) + " points " +
               std::to_string(p.points.size()) + ";";
    ASSERT_EQ(r.result.planes.size(), surfaces.size()) << name << ":" << found;
    std::vector<int> size(surfaces.size(), 0), held(surfaces.size(), 0);
    for (int s : scan.surface) ++size[static_cast<std::size_t>(s)];
    for (const EmPlane& plane : r.result.planes) {
      std::vector<int> votes(surfaces.size(), 0);
      for (int i : plane.points) ++votes[static_cast<std::size_t>(scan.surface[static_cast<std::size_t>(i)])];
      const auto s = static_cast<std::size_t>(std::max_element(votes.begin(), votes.end()) - votes.begin());
      EXPECT_GE(votes[s], 0.9 * static_cast<double>(plane.points.size())) << name << ": plane across surfaces";
      held[s] = std::max(held[s], votes[s]);
      const double error = std::acos(std::min(1.0, std::abs(plane.normal.dot(surfaces[s].normal)))) / kDegree;
      EXPECT_LT(error, max_error_deg) << name << ": surface " << s;
    }
    for (std::size_t s = 0; s < surfaces.size(); ++s)
      EXPECT_GE(held[s], 0.85 * size[s]) << name << ": surface " << s << " of " << size[s] << " points, held " << held[s];
  }
}

// Range noise of 2 cm (a VLP-16's is about 3 cm), and none. Not yet met: EM1, which stops
// before the far wall.
TEST(LidarScan, Em2GivesOnePlanePerSurface) { expect_one_plane_per_surface(0.02, 1.0); }

TEST(LidarScan, Em2GivesOneExactPlanePerSurfaceWithoutNoise) { expect_one_plane_per_surface(0.0, 0.01); }

}  // namespace
}  // namespace relslam::em
