#pragma once
// The non-incremental global index of thesis Fig 110: an OVLPQuadTree rebuilt from every
// mapped point each iteration, O(map size) per iteration. Kept to measure what the
// incremental tree saves. Eigen only.

#include "relslam/spatial/global_index.hpp"
#include "relslam/spatial/ovlp_quadtree.hpp"

#include <vector>

namespace relslam::spatial {

class RebuiltOVLPQuadTree final : public GlobalIndex {
 public:
  RebuiltOVLPQuadTree(double cell_size, double overlap) : grid_(cell_size, overlap) {}

  void place(int id, const Eigen::Vector3d& p) override;
  void remove(int id) override;
  bool contains(int id) const override {
    return id >= 0 && static_cast<std::size_t>(id) < slot_.size() && slot_[id] >= 0;
  }
  void prepare() override { grid_.build(points_); }  // the O(map) reload of every iteration
  std::span<const int> query(const Eigen::Vector3d& q) override;
  std::size_t size() const override { return points_.size(); }

 private:
  OVLPQuadTree grid_;
  std::vector<IndexedPoint> points_;  // every stored point, any order
  std::vector<int> slot_;             // id -> index in points_, or -1
  std::vector<int> found_;
};

}  // namespace relslam::spatial
