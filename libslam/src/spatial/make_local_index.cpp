#include "relslam/spatial/make_local_index.hpp"

#include "relslam/spatial/kd_tree_index.hpp"
#include "relslam/spatial/ovlp_quadtree.hpp"

namespace relslam::spatial {

std::unique_ptr<LocalIndex> make_local_index(LocalIndexKind kind, double cell_size, double radius) {
  switch (kind) {
    case LocalIndexKind::Quadtree: return std::make_unique<OVLPQuadTree>(cell_size, radius);
    case LocalIndexKind::Octree: return std::make_unique<OVLPOctree>(cell_size, radius);
    case LocalIndexKind::KdTree: return std::make_unique<KdTreeIndex>(radius);
  }
  return nullptr;
}

}  // namespace relslam::spatial
