#pragma once
// RltPlaneCompare (thesis 4.4.3.6; spec §2.4, §5.6): the relative pose of two RltPlanes, averaged
// over the iterations both were seen in. Part 1 compares full-size planes by their midpoints;
// part 2 adds the growth-phase split (Rule 18) and the four assumed-midpoint pairs that find
// the key points (Rules 13–15), filling the key-point fields below.

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"
#include "relslam/plane/plane_object.hpp"
#include "relslam/plane/rlt_interval.hpp"

namespace relslam::plane {

class RltPlane;
class RltPlaneInterval;

// Rule 3 for one iteration: `second`'s pose in the frame of `first` turned to 0° —
// P_first⁻¹ ∘ P_second = (Rot(−θ₁)(m₂ − m₁), θ₂ − θ₁), the same from every robot pose (spec
// §2.4). With `rotate_to_first` false: (m₂ − m₁, θ₂ − θ₁), the raw difference of Fig 66.
PlanarPose plane_offset(const PlaneObject& first, const PlaneObject& second, bool rotate_to_first = true);

// What ComparePlanes found (spec §5.6 CompareResult).
struct CompareResult {
  bool valid = false;  // false: no iteration in which both are stored
  // first_T_second: second's reference point in first's, each at its length below.
  PlanarPose delta;
  double length1 = 0;  // the planes' largest lengths in the interval
  double length2 = 0;
  KeyPoint key_point1 = KeyPoint::None;  // part 2 (Rules 13–15)
  KeyPoint key_point2 = KeyPoint::None;
  bool static1 = false;  // part 2: the plane kept its size in the interval (spec §5.6.4)
  bool static2 = false;
  bool ambiguous = false;  // part 2: Rule 15's diagonal tie
  // Part 2: first_T_second of each key-point pair (a, b), index [a − 1][b − 1] (Rule 13): an
  // ambiguous edge is resolved with the planes' key points from elsewhere (Rule 19).
  PlanarPose pair_delta[2][2];
  RltInterval interval;  // first and last iteration used
  int samples = 0;       // iterations averaged
  // Part 2: the chosen key-point pair's σ over the piece (Rule 13; 0 for part 1's midpoints).
  double sigma = 0;
  double height1 = 0;
  double height2 = 0;
};

// ComparePlanes: the mean of plane_offset over every iteration in which both planes have a
// stored observation — the translation averaged, the angle by its circular mean — and, when
// `within` is given, which also lies in it (IntervalMode::Group). One merge walk over the two
// circular arrays, started by binary search: O(log n + interval).
CompareResult compare_planes(const RltPlane& first, const RltPlane& second, bool rotate_to_first = true,
                             const RltPlaneInterval* within = nullptr);

}  // namespace relslam::plane
