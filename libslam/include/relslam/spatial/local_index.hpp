#pragma once
// The spatial index local matching queries (thesis 6.2.4, 6.6.2): rebuilt from the recent
// points every iteration, asked for the candidates near each observation. Eigen only.

#include <Eigen/Core>

#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace relslam::spatial {

struct IndexedPoint {
  int id = 0;
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
};

// Invariant of every implementation: query(q) contains each built point within Euclidean
// distance `radius` (fixed at construction) of q; it may contain others, callers test exact
// distances.
class LocalIndex {
 public:
  virtual ~LocalIndex() = default;
  virtual void build(const std::vector<IndexedPoint>& points) = 0;
  virtual std::span<const IndexedPoint> query(const Eigen::Vector3d& q) = 0;
};

enum class LocalIndexKind {
  Quadtree,  // overlapping uniform grid over x and z (the thesis's OVLPQuadTree)
  Octree,    // the same over x, y and z: more cells to fill, fewer candidates (thesis 6.6.2)
  KdTree,    // k-d tree rebuilt each iteration, radius search (the thesis's side experiment)
};
std::string_view to_string(LocalIndexKind kind);
std::optional<LocalIndexKind> parse_local_index(std::string_view name);

// make_local_index.hpp builds one.

}  // namespace relslam::spatial
