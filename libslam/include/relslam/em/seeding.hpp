#pragma once
// Seeding a new random plane (thesis 3.5.2 step 6, 3.5.3 step 4; spec §4.2 "Seeding"). Eigen only.

#include "relslam/em/em_plane.hpp"
#include "relslam/em/options.hpp"

#include <optional>
#include <span>

namespace relslam::em {

// The plane through `start` (the caller's random unassigned point) and its two nearest points
// among `candidates` (unassigned points; `start` itself is skipped), ties broken by the lower
// index so the result does not depend on the candidates' order. Nothing when the two are not
// both within options.seed_radius, or the three points are nearly collinear
// (|a × b| / (|a||b|) < options.min_seed_sine). The plane has age 0 and its three points.
std::optional<EmPlane> seed_plane(std::span<const Eigen::Vector3d> points, int start,
                                  std::span<const int> candidates, const EmOptions& options);

}  // namespace relslam::em
