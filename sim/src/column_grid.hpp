#pragma once
// Internal to relslam_sim: static landmarks bucketed by horizontal cell, so a frame only
// tests the landmarks of cells that can reach the frustum.

#include <Eigen/Core>
#include <vector>

namespace relslam::sim {

// Invariant: every static landmark id appears in exactly one cell, and each cell's sphere
// (centre, radius) encloses all of its landmarks.
class ColumnGrid {
 public:
  struct Cell {
    Eigen::Vector3d centre;
    double radius;
    int begin, end;  // range in ids()
  };

  ColumnGrid(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& ids, double cell_size);
  const std::vector<Cell>& cells() const { return cells_; }
  const std::vector<int>& ids() const { return ids_; }

 private:
  std::vector<Cell> cells_;
  std::vector<int> ids_;
};

}  // namespace relslam::sim
