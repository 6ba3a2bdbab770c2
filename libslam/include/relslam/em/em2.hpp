#pragma once
// EM algorithm 2, "incremental": one random plane at a time is grown within its seed's cell of
// an overlapping grid, checked for density, and never revisited; about twice as fast as EM1
// (thesis 3.5.3, 3.5.4). Eigen only.

#include "relslam/em/em_plane.hpp"
#include "relslam/em/options.hpp"

#include <cstdint>
#include <span>

namespace relslam::em {

// The planes of one frame's points (robot frame), from scratch, with the EM stream seeded by
// `seed` (em_frame_seed). Non-finite points are ignored. Per EM iteration (thesis 3.5.3): the
// unassigned points (usage 0) are listed; one random one seeds a plane with its two nearest
// unassigned neighbours from the grid; the plane grows for at most em2.grow_rounds rounds (widen
// the box by bound_expansion, gather the accepted points of the seed's grid cell, refit, density
// check), stopping early once its points no longer change; it is kept if it has min_support
// points, its points' usage goes up, and it merges with any earlier plane it matches. The loop
// ends when at most max(em2.left_min, em2.left_fraction · points) points are unassigned, after
// em2.max_iterations, or after seed_attempts failed planes in a row. Last, the exclusivity cull
// and the rectangles.
//
// Deviation (thesis 3.5.3 tests the support after every growth round): the support is tested once
// growth has ended. A 3-point seed's first round reaches about (3·e_exp)² of wall, some 20
// points at the default spacing, so the literal test drops most seeds before they can grow (the
// same reason as EM1's culls sparing fresh seeds, thesis 3.5.2). A plane that yields nothing
// (seeding or growth fails) counts as a failure for the stop rule [R].
// Requires check(options) to be empty (throws std::logic_error otherwise).
EmResult run_em2(std::span<const Eigen::Vector3d> points, const EmOptions& options, std::uint64_t seed);

}  // namespace relslam::em
