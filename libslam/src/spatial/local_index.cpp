#include "relslam/spatial/local_index.hpp"

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

}  // namespace relslam::spatial
