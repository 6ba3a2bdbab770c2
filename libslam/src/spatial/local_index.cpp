#include "relslam/spatial/local_index.hpp"

#include "relslam/spatial/kd_tree_index.hpp"
#include "relslam/spatial/ovlp_quadtree.hpp"

namespace relslam::spatial {

std::string_view to_string(LocalIndexKind kind) {
  switch (kind) {
    case LocalIndexKind::Quadtree: return "quadtree";
    case LocalIndexKind::Octree: return "octree";
    case LocalIndexKind::KdTree: return "kdtree";
  }
  return "?";
}

std::optional<LocalIndexKind> parse_local_index(std::string_view name) {
  for (LocalIndexKind k : {LocalIndexKind::Quadtree, LocalIndexKind::Octree, LocalIndexKind::KdTree})
    if (name == to_string(k)) return k;
  return std::nullopt;
}

std::unique_ptr<LocalIndex> make_local_index(LocalIndexKind kind, double cell_size, double radius) {
  switch (kind) {
    case LocalIndexKind::Quadtree: return std::make_unique<OVLPQuadTree>(cell_size, radius);
    case LocalIndexKind::Octree: return std::make_unique<OVLPOctree>(cell_size, radius);
    case LocalIndexKind::KdTree: return std::make_unique<KdTreeIndex>(radius);
  }
  return nullptr;
}

}  // namespace relslam::spatial
