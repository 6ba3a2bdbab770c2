#pragma once
// ReorderPlanes (thesis 4.3.7 Rule 30; thesis 4.3.7.1): a group's comparison
// chain is first the order its planes joined in, which may pair two planes whose comparison has
// no usable key points (the collinear shrink + grow of Fig 97, Rule 15's tie) or only a short
// interval. Rule 30 re-orders the chain so the pairs compared share the longest intervals with
// valid key points. The thesis searched paths visiting each plane once (it left the tree, "a
// travelling salesman problem", undone). Part of relslam/plane: a pure function of the weights.

#include <optional>
#include <vector>

namespace relslam::plane {

// `weight[i][j]` (symmetric, n × n): the iterations of ComparePlanes(i, j)'s chosen interval when
// its key points are valid, negative when the pair may not be an edge. The best Hamiltonian path
// by total weight over usable edges, as a visiting order of 0..n−1: exact (bitmask dynamic
// programming, O(2ⁿ·n²)) for n ≤ `exact_max`, otherwise the best of the greedy paths from each
// start (always on to the unvisited plane with the largest weight) [R, thesis 4.3.7.1]. Ties go to the
// first found in index order (deterministic); of a path and its reverse, the one starting at the
// smaller index. nullopt when no path uses usable edges only (the caller keeps its order) or n < 2.
std::optional<std::vector<int>> best_comparison_path(const std::vector<std::vector<int>>& weight, int exact_max);

}  // namespace relslam::plane
