#pragma once
// OVLPQuadTree and OVLPOctree (thesis 6.2.4, 6.6.2): overlapping uniform grids, rebuilt from
// scratch each time. Eigen only.

#include "relslam/spatial/local_index.hpp"

#include <array>
#include <span>
#include <vector>

namespace relslam::spatial {

// Despite the thesis's names, uniform grids over 2 axes (x and z: the horizontal plane of the
// robot and the world frame; y is left to the exact distance test) or 3 (x, y, z). Each cell
// also holds the points within `overlap` of it, so one cell answers a query (thesis 6.2.4:
// cheaper than visiting neighbours; the 3-D grid fills up to 26 neighbours instead of 8).
// Invariant: query(q) contains every built point within L∞ distance `overlap` of q on the
// grid's axes.
template <int Axes>
class OverlappingGrid final : public LocalIndex {
 public:
  // overlap <= cell_size (a point then reaches only its direct neighbour cells).
  OverlappingGrid(double cell_size, double overlap);

  // Covers the points' bounding box (so nothing is clamped); O(n). Keeps its memory between
  // builds: the local index is rebuilt every iteration (thesis 6.2.5).
  void build(const std::vector<IndexedPoint>& points) override;
  std::span<const IndexedPoint> query(const Eigen::Vector3d& q) override;
  double cell_size() const { return cell_; }

 private:
  static constexpr std::array<int, 3> kAxis = Axes == 2 ? std::array<int, 3>{0, 2, 0} : std::array<int, 3>{0, 1, 2};
  int cell_of(const Eigen::Vector3d& p, std::array<int, Axes>* index = nullptr) const;
  template <class Visit>
  void for_each_cell_of(const Eigen::Vector3d& p, Visit visit) const;

  double base_cell_;  // as constructed; a build may use larger cells for a huge spread
  double cell_;
  double overlap_;
  std::array<double, Axes> origin_{};
  std::array<int, Axes> extent_{};  // cells per axis
  std::vector<int> start_;          // CSR offsets into entries_, one per cell plus one
  std::vector<IndexedPoint> entries_;
  std::vector<int> fill_;   // scratch for build
  std::vector<int> cells_;  // scratch for build: each point's cells, -1 after each point
};

using OVLPQuadTree = OverlappingGrid<2>;
using OVLPOctree = OverlappingGrid<3>;

}  // namespace relslam::spatial
