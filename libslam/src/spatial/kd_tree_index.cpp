#include "relslam/spatial/kd_tree_index.hpp"

#include <nanoflann.hpp>

namespace relslam::spatial {
namespace {

struct Points {
  std::vector<IndexedPoint> points;
  std::size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const { return points[i].p[static_cast<int>(dim)]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using Tree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Points>, Points, 3, std::uint32_t>;

}  // namespace

struct KdTreeIndex::Tree {
  Points data;
  std::unique_ptr<spatial::Tree> index;
  std::vector<std::pair<std::uint32_t, double>> matches;
};

KdTreeIndex::KdTreeIndex(double radius) : radius_(radius), tree_(std::make_unique<Tree>()) {}
KdTreeIndex::~KdTreeIndex() = default;

void KdTreeIndex::build(const std::vector<IndexedPoint>& points) {
  tree_->data.points = points;
  tree_->index = std::make_unique<spatial::Tree>(3, tree_->data, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  tree_->index->buildIndex();
}

std::span<const IndexedPoint> KdTreeIndex::query(const Eigen::Vector3d& q) {
  found_.clear();
  if (tree_->data.points.empty()) return {};
  nanoflann::SearchParams params;
  params.sorted = false;
  // L2_Simple works in squared distances; a hair of slack keeps boundary points in.
  tree_->index->radiusSearch(q.data(), radius_ * radius_ * (1.0 + 1e-12), tree_->matches, params);
  for (const auto& [i, d2] : tree_->matches) found_.push_back(tree_->data.points[i]);
  return found_;
}

std::optional<IndexedPoint> KdTreeIndex::nearest(const Eigen::Vector3d& q) const {
  if (tree_->data.points.empty()) return std::nullopt;
  std::uint32_t i = 0;
  double d2 = 0;
  tree_->index->knnSearch(q.data(), 1, &i, &d2);
  return tree_->data.points[i];
}

}  // namespace relslam::spatial
