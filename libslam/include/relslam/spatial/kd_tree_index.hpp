#pragma once
// A k-d tree local index (thesis 6.6.2's side experiment: slower than the overlapping grid
// at both building and querying). nanoflann inside; this header is Eigen only.

#include "relslam/spatial/local_index.hpp"

#include <memory>
#include <optional>

namespace relslam::spatial {

// Exact radius search: query(q) is precisely the points within `radius`.
class KdTreeIndex final : public LocalIndex {
 public:
  explicit KdTreeIndex(double radius);
  ~KdTreeIndex() override;
  void build(const std::vector<IndexedPoint>& points) override;
  std::span<const IndexedPoint> query(const Eigen::Vector3d& q) override;
  // The built point closest to q (nothing when empty); the evaluation's nearest-truth lookups.
  std::optional<IndexedPoint> nearest(const Eigen::Vector3d& q) const;

 private:
  struct Tree;
  double radius_;
  std::unique_ptr<Tree> tree_;
  std::vector<IndexedPoint> found_;
};

}  // namespace relslam::spatial
