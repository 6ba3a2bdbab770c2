#pragma once
// Seeding a new random plane (thesis 3.5.2 step 6, 3.5.3 step 4; "Seeding"). Eigen only.

#include "relslam/em/em_plane.hpp"
#include "relslam/em/options.hpp"

#include <optional>
#include <span>

namespace relslam::em {

// The plane through `start` (the caller's random unassigned point), its nearest point among
// `candidates` (unassigned points; `start` itself is skipped) and the nearest one that is not
// nearly collinear with those two (|a × b| / (|a||b|) >= options.min_seed_sine), ties broken by
// the lower index so the result does not depend on the candidates' order. Nothing when no such
// two lie within options.seed_radius. The plane has age 0 and its three points.
// Deviation (the thesis and thesis 3.5 take the two nearest and fail when they are collinear):
// on a sensor's regular grid (an image row, a scan line) the two nearest of a point are its
// neighbours on the row, always collinear, so nearly every seed failed on depth frames [C].
std::optional<EmPlane> seed_plane(std::span<const Eigen::Vector3d> points, int start,
                                  std::span<const int> candidates, const EmOptions& options);

}  // namespace relslam::em
