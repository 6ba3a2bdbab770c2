#include "relslam/em/cloud_summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace relslam::em {
namespace {

CloudSummary sample_image(std::span<const Eigen::Vector3d> points, int width, int height, int stride) {
  CloudSummary s;
  s.stride = stride;
  s.columns = (width + stride - 1) / stride;
  s.rows = (height + stride - 1) / stride;
  s.grid.assign(static_cast<std::size_t>(s.columns) * static_cast<std::size_t>(s.rows), -1);
  for (int r = 0; r < s.rows; ++r)
    for (int c = 0; c < s.columns; ++c) {
      const int pixel = r * stride * width + c * stride;
      const Eigen::Vector3d& p = points[static_cast<std::size_t>(pixel)];
      if (!p.allFinite()) continue;
      s.grid[static_cast<std::size_t>(r * s.columns + c)] = static_cast<int>(s.points.size());
      s.points.push_back(p);
      s.source.push_back(pixel);
    }
  return s;
}

// Voxel key: three 21-bit cell indices (±1e6 cells each way; farther points share the edge cell,
// which only thins them further).
std::uint64_t voxel_key(const Eigen::Vector3d& p, double edge) {
  std::uint64_t key = 0;
  for (int a = 0; a < 3; ++a) {
    const double cell = std::clamp(std::floor(p[a] / edge), -1048575.0, 1048575.0);
    key = (key << 21) | (static_cast<std::uint64_t>(static_cast<std::int64_t>(cell) + 1048576) & 0x1FFFFF);
  }
  return key;
}

struct Voxel {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  int best = -1;
  double best_distance = 0;
};

}  // namespace

CloudSummary summarise_image(std::span<const Eigen::Vector3d> points, int width, int height, int target) {
  int finite = 0;
  for (const Eigen::Vector3d& p : points) finite += p.allFinite();
  // Kept points fall about as stride²: start from that estimate, step up while too many.
  int stride = std::max(1, static_cast<int>(std::floor(std::sqrt(static_cast<double>(finite) / std::max(1, target)))));
  CloudSummary s = sample_image(points, width, height, stride);
  while (static_cast<int>(s.points.size()) > target && stride < std::max(width, height))
    s = sample_image(points, width, height, ++stride);
  return s;
}

CloudSummary summarise_voxels(std::span<const Eigen::Vector3d> points, int target, double voxel) {
  CloudSummary s;
  std::vector<int> finite;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].allFinite()) finite.push_back(static_cast<int>(i));
  if (static_cast<int>(finite.size()) <= target) {
    for (int i : finite) s.points.push_back(points[static_cast<std::size_t>(i)]);
    s.source = std::move(finite);
    return s;
  }
  std::unordered_map<std::uint64_t, Voxel> voxels;
  for (double edge = voxel;; edge *= 2.0) {
    voxels.clear();
    bool fits = true;
    for (int i : finite) {
      Voxel& v = voxels[voxel_key(points[static_cast<std::size_t>(i)], edge)];
      v.sum += points[static_cast<std::size_t>(i)];
      ++v.count;
      if (static_cast<int>(voxels.size()) > target) {
        fits = false;
        break;
      }
    }
    if (!fits) continue;
    s.voxel = edge;
    for (int i : finite) {  // the point nearest its voxel's centroid; ties: the first
      const Eigen::Vector3d& p = points[static_cast<std::size_t>(i)];
      Voxel& v = voxels[voxel_key(p, edge)];
      const double d = (p - v.sum / v.count).squaredNorm();
      if (v.best < 0 || d < v.best_distance) v.best = i, v.best_distance = d;
    }
    // In cloud order, so the summary does not depend on the hash map's iteration order.
    for (int i : finite) {
      const Voxel& v = voxels[voxel_key(points[static_cast<std::size_t>(i)], edge)];
      if (v.best != i) continue;
      s.points.push_back(points[static_cast<std::size_t>(i)]);
      s.source.push_back(i);
    }
    return s;
  }
}

}  // namespace relslam::em
