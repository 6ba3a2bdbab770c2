#pragma once
// EM algorithm 1, "batch": every EM iteration re-assigns every point to every plane (E-step),
// seeds new random planes from the unassigned points, refits (M-step), merges and culls
// (thesis 3.5.2). Eigen only.

#include "relslam/em/em_plane.hpp"
#include "relslam/em/options.hpp"

#include <cstdint>
#include <span>

namespace relslam::em {

// The planes of one frame's points (robot frame), from scratch (thesis 3.5.1: no warm start), with
// the EM stream seeded by `seed` (em_frame_seed). Non-finite points are ignored; an empty or
// planeless input gives no planes. The loop of thesis 3.5.2, with its [R] readings: the support
// and exclusivity culls spare planes younger than em1.cull_age E-steps (a deviation: a literal reading
// spares only age 0, see Em1Options::cull_age), and the
// iteration stops (after the E-step) when em1.done_fraction of the points is assigned, after
// em1.max_iterations, or when em1.patience iterations brought no new established plane and no
// growth in the assigned points. Then,
// once more for every plane: refit, merge, both culls, rectangles [R: the last E-step's fresh
// seeds would otherwise leave unculled].
// Requires check(options) to be empty (throws std::logic_error otherwise).
EmResult run_em1(std::span<const Eigen::Vector3d> points, const EmOptions& options, std::uint64_t seed);

}  // namespace relslam::em
