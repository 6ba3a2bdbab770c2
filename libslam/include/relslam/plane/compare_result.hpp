#pragma once
// CompareResult: what a comparison of two planes found — their relative pose, averaged over the
// iterations both were seen in, and the key points it rests on. Its own header because it is the
// common currency of the comparisons (rlt_plane_compare, key_point_compare, pair_comparison) and of
// what keeps their results (rlt_xpoint_ref, rlt_xpoint), and those sit on both sides of RltPlane.

#include "relslam/core/planar_pose.hpp"
#include "relslam/plane/plane_object.hpp"
#include "relslam/plane/rlt_interval.hpp"

namespace relslam::plane {

// What ComparePlanes found.
struct CompareResult {
  bool valid = false;  // false: no iteration in which both are stored
  // first_T_second: second's reference point in first's, each at its length below.
  PlanarPose delta;
  double length1 = 0;  // the planes' largest lengths in the interval
  double length2 = 0;
  KeyPoint key_point1 = KeyPoint::None;  // part 2 (Rules 13–15)
  KeyPoint key_point2 = KeyPoint::None;
  bool static1 = false;  // part 2: the plane kept its size in the interval
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

}  // namespace relslam::plane
