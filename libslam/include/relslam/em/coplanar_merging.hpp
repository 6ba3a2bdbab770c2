#pragma once
// Merging planes that one plane holds, for clouds whose points lie along scan lines (a lidar's
// rings): dense along a line, sparse across. EM grows a plane only over points within e_exp of
// its box and merges planes whose equations agree (merging.hpp), so on a multi-line lidar each
// line's arc of the ground becomes a plane of its own: the next line lies farther than e_exp,
// and an arc, nearly a straight line, fixes its plane's tilt about itself poorly, so the arcs'
// equations disagree. Their union still fits one plane, and that is the test here: the thesis's
// merge (3.5.2 step 8, 3.5.3 step 7) asks whether two planes model one surface; for pieces of
// scan lines the joint fit answers it where their own equations cannot. Eigen only.

#include "relslam/em/em_plane.hpp"
#include "relslam/em/options.hpp"

#include <span>
#include <vector>

namespace relslam::em {

// Two planes are coplanar when the TLS fit of their joint points holds at least
// kCoplanarShare of each plane's points within d_in (inlier_distance_at), and their boxes lie
// at most e_exp + gap_per_range · r apart, r the smaller of their points' mean ranges (the spacing
// across scan lines grows with the range, and on a surface seen at a grazing angle, the ground,
// much faster).
bool coplanar(const EmPlane& a, const EmPlane& b, std::span<const Eigen::Vector3d> points, const EmOptions& o,
              double gap_per_range);

// Merges coplanar pairs as merge_planes does (merge_planes_where). Returns the number of merges.
int merge_coplanar(std::vector<EmPlane>& planes, std::span<const Eigen::Vector3d> points, const EmOptions& o,
                   double gap_per_range);

}  // namespace relslam::em
