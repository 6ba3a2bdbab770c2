#pragma once
// RltPlaneCompare (thesis 4.4.3.6; thesis 4.3.1, 4.3.4): the relative pose of two RltPlanes, averaged
// over the iterations both were seen in. Part 1 compares full-size planes by their midpoints;
// part 2 adds the growth-phase split (Rule 18) and the four assumed-midpoint pairs that find
// the key points (Rules 13–15), filling the key-point fields below.

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"
#include "relslam/plane/compare_result.hpp"
#include "relslam/plane/plane_object.hpp"

namespace relslam::plane {

class RltPlane;
class RltPlaneInterval;

// Rule 3 for one iteration: `second`'s pose in the frame of `first` turned to 0° —
// P_first⁻¹ ∘ P_second = (Rot(−θ₁)(m₂ − m₁), θ₂ − θ₁), the same from every robot pose.
// With `rotate_to_first` false: (m₂ − m₁, θ₂ − θ₁), the raw difference of Fig 66.
PlanarPose plane_offset(const PlaneObject& first, const PlaneObject& second, bool rotate_to_first = true);

// ComparePlanes: the mean of plane_offset over every iteration in which both planes have a
// stored observation — the translation averaged, the angle by its circular mean — and, when
// `within` is given, which also lies in it (IntervalMode::Group). One merge walk over the two
// circular arrays, started by binary search: O(log n + interval).
CompareResult compare_planes(const RltPlane& first, const RltPlane& second, bool rotate_to_first = true,
                             const RltPlaneInterval* within = nullptr);

}  // namespace relslam::plane
