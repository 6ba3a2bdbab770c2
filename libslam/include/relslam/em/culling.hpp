#pragma once
// Removing planes that should not be there: too few points (minimum support) and too few
// points of their own (exclusivity), thesis 3.5.2 steps 9–10, 3.5.3 step 9. Eigen only.

#include "relslam/em/em_plane.hpp"
#include "relslam/em/options.hpp"

#include <cstddef>
#include <vector>

namespace relslam::em {

// Removes planes with fewer than options.min_support points, sparing planes younger than
// `min_age` E-steps: a fresh 3-point seed would otherwise never get to grow (
// em1.cull_age). Returns the number removed.
int cull_min_support(std::vector<EmPlane>& planes, const EmOptions& options, int min_age);

// Removes, one at a time, the plane with the smallest share of points owned by no other plane
// while that share is below options.min_exclusive_fraction (ties: the later plane), recounting
// after each removal: the bridge plane at a corner shares all its points with the two walls
// (exclusivity ≈ 0) and goes first, after which the walls' points are their own again. Only
// planes with age >= min_age are candidates. `count` = the frame's point count. Nothing
// happens when options.exclusivity_cull is off. Returns the number removed.
int cull_exclusivity(std::vector<EmPlane>& planes, std::size_t count, const EmOptions& options, int min_age);

}  // namespace relslam::em
