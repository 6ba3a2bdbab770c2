#pragma once
// RltXPointLink (thesis 4.4.3.9): how a group was chained onto an older one.

#include "relslam/plane/ids.hpp"

#include <vector>

namespace relslam::plane {

// Made with the group `to`; RltXPointsS keeps them in creation order, so BuildMap is one pass
// over the list (thesis 4.4.3.1). The first link places X0 by Rule 4 and has no `from`.
struct RltXPointLink {
  XPointId from = kNone;
  XPointId to = kNone;
  std::vector<PlaneId> planes;  // the linking planes, in both groups (Rule 8: two)
  bool first = false;
  int created_iteration = 0;
};

}  // namespace relslam::plane
