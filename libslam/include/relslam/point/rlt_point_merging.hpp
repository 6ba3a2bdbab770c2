#pragma once
// RltPoint merging (thesis 6.5.2): a new RltPoint that turns out to be an old landmark
// found again (global matching missed it) is merged into the old RltPoint. Eigen only.

#include "relslam/point/rlt_map.hpp"

#include <deque>
#include <utility>

namespace relslam::point {

// The merge checks waiting for their iteration, in due order.
class RltPointMerging {
 public:
  // A new RltPoint is checked once, at iteration `due` (creation + merge_delay): by then its
  // groups have placed it on the map.
  void schedule(PointId id, int due) { checks_.emplace_back(due, id); }

  // Runs every check due by iteration k: a point on the map with a merge partner within
  // `bound` is merged into it. Returns the number of merges.
  int merge_due(RltMap& map, int k, double bound);

 private:
  std::deque<std::pair<int, PointId>> checks_;  // (iteration due, point)
};

// The closest older point on the map within `bound` of point `id`'s map position that was never
// seen while `id` was (seen together they are two landmarks; disjoint, the observation ring
// stays in order after the merge); kNone if there is none or `id` is not on the map.
PointId merge_partner(RltMap& map, PointId id, double bound);

// Merges RltPoint `newer` into `older` at iteration k (thesis 6.5.2): the older point takes
// every observation; the older point's groups accumulate the copied iterations; each group of
// the newer point holds the older one instead, as an anchor (same observations, so its sums stay
// valid; the map position stays the older point's), unless the group holds both, which retires
// it; the newer point leaves the lists, the index and the charting, flagged merged.
void merge_points(RltMap& map, PointId newer, PointId older, int k);

}  // namespace relslam::point
