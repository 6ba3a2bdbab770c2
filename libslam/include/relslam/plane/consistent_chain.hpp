#pragma once
// A comparison chain through consistent ends (beyond Rule 30, thesis 4.3.7.1; adaptive preset with
// relative_plane.grounded_map). Rule 28 joins two edges at a plane by moving the plane's reference
// point between the sizes the edges saw it at (Fig 87); that is right only when both edges
// anchored the plane on the same end, or the plane was seen whole. A piece the sensor never saw
// whole, anchored on its left end by one edge and on its right end by the next, says nothing about
// how far along the wall one end lies from the other: the chain breaks there
// (RltXPoint::chain_with_size_correction). Another order of the same planes can pass every plane
// on one end: a wall seen whole between two pieces, or each piece entered and left on its real end.
// Part of relslam/plane: a pure function of the comparisons' weights and ends.

#include "relslam/plane/plane_object.hpp"

#include <optional>
#include <vector>

namespace relslam::plane {

// `weight[i][j]` as for best_comparison_path (reorder_planes.hpp): the iterations of
// ComparePlanes(i, j) when it places both planes, negative when the pair may not be an edge.
// `end[i][j]`: the end of plane i the comparison (i, j) anchored it on; KeyPoint::None where
// plane i needs no end there (it kept its size in that comparison, or was seen whole). The best
// Hamiltonian path by total weight over usable edges in which every inner plane has the same end,
// or None, in its two edges; exact (dynamic programming over subsets, the last plane and the end
// it was entered on) up to `exact_max` planes (and 16), nullopt beyond, when no such path exists,
// or n < 2. Of a path and its reverse, the one starting at the smaller index.
std::optional<std::vector<int>> best_consistent_path(const std::vector<std::vector<int>>& weight,
                                                     const std::vector<std::vector<KeyPoint>>& end, int exact_max);

// Whether the chain order (plane indices) passes every inner plane on one end (as above); a chain
// with a negative-weight edge is not.
bool consistent_chain(const std::vector<int>& order, const std::vector<std::vector<int>>& weight,
                      const std::vector<std::vector<KeyPoint>>& end);

}  // namespace relslam::plane
