#pragma once
// The factory of LocalIndex: the one place that maps LocalIndexKind to an implementation. In its
// own file so that the implementations, which include local_index.hpp, are not included back by it.

#include "relslam/spatial/local_index.hpp"

#include <memory>

namespace relslam::spatial {

// cell_size is the grid cell (quadtree, octree); radius the matching bound.
std::unique_ptr<LocalIndex> make_local_index(LocalIndexKind kind, double cell_size, double radius);

}  // namespace relslam::spatial
