#include "column_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace relslam::sim {

ColumnGrid::ColumnGrid(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& ids, double cell_size) {
  // Cells are vertical columns over the world x–z plane (y is up).
  auto key = [&](int id) {
    const auto ix = static_cast<std::int64_t>(std::floor(points[id].x() / cell_size));
    const auto iz = static_cast<std::int64_t>(std::floor(points[id].z() / cell_size));
    return std::pair{ix, iz};
  };
  ids_ = ids;
  std::stable_sort(ids_.begin(), ids_.end(), [&](int a, int b) { return key(a) < key(b); });
  for (int begin = 0; begin < static_cast<int>(ids_.size());) {
    int end = begin + 1;
    while (end < static_cast<int>(ids_.size()) && key(ids_[end]) == key(ids_[begin])) ++end;
    Eigen::Vector3d lo = points[ids_[begin]], hi = lo;
    for (int i = begin; i < end; ++i) {
      lo = lo.cwiseMin(points[ids_[i]]);
      hi = hi.cwiseMax(points[ids_[i]]);
    }
    cells_.push_back({(lo + hi) / 2.0, (hi - lo).norm() / 2.0, begin, end});
    begin = end;
  }
}

}  // namespace relslam::sim
