#pragma once
// EM2's density check (thesis 3.5.3 step 5: "start from the random point again and see how the
// point density of the plane changes as the plane is gradually expanded. If the density becomes
// too low then stop expanding and remove any points that are not in the higher density portion
// of the plane"; thesis 3.5.3 makes it concrete [R]). Eigen only.

#include "relslam/em/em_plane.hpp"
#include "relslam/em/options.hpp"

#include <span>
#include <vector>

namespace relslam::em {

// The plane's points kept by the check. In the plane's own coordinates (s along its horizontal
// tangent, t across it in the plane; y for a wall) centred on the seed point, a rectangle grows
// from the central square [−δ, δ]² by δ = em2.density_step at a time, in the order +s, −s, +t,
// −t, each direction until its new strip's density falls below em2.density_fraction × the
// central square's (an empty strip always stops). A strip's density is taken over the depth
// its farthest point reaches into it, so the partly filled strip at a wall's end does not cut
// off the end [C: a full-strip density trimmed up to a step off every wall end, and
// the dropped points seeded small planes at corners]. Points outside the final rectangle are
// dropped. With no seed point, or an empty central square, every point is kept.
std::vector<int> density_check(std::span<const Eigen::Vector3d> points, const EmPlane& plane,
                               const EmOptions& options);

}  // namespace relslam::em
