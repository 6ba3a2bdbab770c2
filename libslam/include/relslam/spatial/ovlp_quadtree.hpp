#pragma once
// OVLPQuadTree (thesis 6.2.4): an overlapping uniform grid, rebuilt from scratch each time.
// Eigen only.

#include <Eigen/Core>

#include <span>
#include <vector>

namespace relslam::spatial {

struct IndexedPoint {
  int id = 0;
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
};

// Despite the thesis's name, a uniform grid over two axes (x and z: the horizontal plane of
// both the robot and the world frame); y is left to the caller's exact distance test.
// Each cell also holds the points within `overlap` of it, so one cell answers a query
// (thesis 6.2.4: cheaper than visiting neighbours).
// Invariant: query(q) contains every built point within L∞ distance `overlap` of q in x and z.
class OVLPQuadTree {
 public:
  // overlap <= cell_size (a point then reaches only its 8 neighbour cells).
  OVLPQuadTree(double cell_size, double overlap);

  // Covers the points' bounding box (so nothing is clamped); O(n). Keeps its memory between
  // builds: the local index is rebuilt every iteration (thesis 6.2.5).
  void build(const std::vector<IndexedPoint>& points);
  std::span<const IndexedPoint> query(const Eigen::Vector3d& q) const;
  double cell_size() const { return cell_; }

 private:
  template <class Visit>
  void for_each_cell_of(const Eigen::Vector3d& p, Visit visit) const;
  int cell_index(double x, double z) const;

  double base_cell_;  // as constructed; a build may use larger cells for a huge spread
  double cell_;
  double overlap_;
  double x0_ = 0, z0_ = 0;
  int columns_ = 0, rows_ = 0;
  std::vector<int> start_;          // CSR offsets into entries_, one per cell plus one
  std::vector<IndexedPoint> entries_;
  std::vector<int> fill_;           // scratch for build
};

}  // namespace relslam::spatial
