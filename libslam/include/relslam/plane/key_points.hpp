#pragma once
// Key points (thesis 4.3.4, Rules 13–15; thesis 4.2.3, 4.3.4): which
// end of each of two clipped planes stayed put while they were compared. A plane cut by the
// frustum grows or shrinks at its cut end only, so of the four offsets between the planes'
// assumed midpoints (one from each top corner, at the plane's maximum length) the one between
// the two real ends stays constant: the pair with the lowest standard deviation names the key
// points. Part of relslam/plane: Eigen only.

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"
#include "relslam/plane/plane_object.hpp"

#include <Eigen/Core>

#include <array>
#include <span>
#include <vector>

namespace relslam::plane {

// When two standard deviations count as equal (thesis 4.3.4): close(x, y) ⇔
// |x − y| ≤ max(absolute, relative·max(x, y)). Noise makes two static pairs differ a little; the
// relative part covers that, the absolute part the noise-free case where both are ~1e-16.
struct KeyPointTies {
  double relative = 0.3;    // [R, r_tie]
  double absolute = 0.002;  // units [R, ε_σ]
  // The distance test the thesis proposes for Fig 97 (4.3.7.1): two collinear pieces of one
  // wall line, one shrinking exactly as the other grows, tie on both diagonals (Rule 15), and
  // one diagonal is wrong. The right one joins the two static ends, which lie between the cut
  // ones, so "if one of the two is shorter, use the shorter one" [T suggestion; C: on]. Parallel
  // planes that are not collinear keep Rule 15 (there the two distances are the same [T]).
  bool collinear_distance = true;
  double collinear_angle_deg = 3;  // collinear: directions within this, degrees [C] ...
  double collinear_offset = 0.1;   // ... and on one line within this, units [C: 10 σ_p]
  // Rule 15's diagonal tie from a short piece. A σ over n samples is itself uncertain: the pooled
  // 2-D spread has 2(n − 1) degrees of freedom, so its relative standard error is about
  // 1 / (2√(n − 1)), and two estimates of one σ differ by chance by √2 of that. The diagonals
  // also tie when they differ by at most `small_sample_z` such errors of their mean (at z = 2:
  // a ratio up to 1.9 over 6 samples, 1.35 over 23 — where `relative` takes over). A plane
  // entering the view as a sliver while the robot drives past it and its partner (both cut by
  // the frustum, both real ends moving together) otherwise takes the cut ends as its key points,
  // and its group is placed a wall's length off (Map D, seed 5, iteration 1776: σ 0.015 against
  // 0.022 over 6 samples; 9 walls then mapped twice). [C] 2; 0: `relative` alone.
  double small_sample_z = 2;

  bool close(double x, double y) const;
  // close(), with the relative part widened for σ taken over `samples` iterations
  // (small_sample_z): Rule 15's diagonal tie.
  bool close_over(double x, double y, int samples) const;
};

// Rule 13's four cross-pair offset series over one interval, reduced to their means and spreads.
// Pair (a, b) compares the first plane's assumed midpoint from key point a with the second's from
// key point b; index [a − 1][b − 1]. Each offset is taken in the first plane's frame turned to 0°
// (Rule 3), and the key-point numbering is fixed by Rule 14, so one pair means the same two ends
// at every iteration however the robot turns.
struct KeyPointPairs {
  int samples = 0;     // iterations compared
  double length1 = 0;  // L1, L2: the planes' maximum lengths in the interval — the size the
  double length2 = 0;  // assumed midpoints are built with (thesis 4.3.4 "maximum size")
  Eigen::Vector2d mean[2][2] = {{Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()},
                                {Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()}};
  // Pooled 2-D standard deviation sqrt(mean |off − mean|²).
  double sigma[2][2] = {{0, 0}, {0, 0}};
  double angle = 0;  // circular mean of θ₂ − θ₁, the same for all four pairs

  double sigma_of(KeyPoint a, KeyPoint b) const { return sigma[index(a)][index(b)]; }
  // first_T_second of pair (a, b): the second plane's length-L2 reference point anchored at b, in
  // the frame of the first's length-L1 reference point anchored at a (thesis 4.3.4).
  PlanarPose delta(KeyPoint a, KeyPoint b) const { return {mean[index(a)][index(b)], angle}; }

 private:
  static int index(KeyPoint k) { return k == KeyPoint::Right ? 1 : 0; }
};

// One sample of pair (a, b)'s series (Rule 13): the offset from the first plane's assumed midpoint
// at length1 from key point a to the second's at length2 from key point b, in the first plane's
// frame turned to 0° (raw with `rotate_to_first` false).
Eigen::Vector2d key_point_offset(const PlaneObject& first, const PlaneObject& second, double length1, double length2,
                                 KeyPoint a, KeyPoint b, bool rotate_to_first = true);

// One iteration's four offsets of Rule 13, pair (a, b) at [2(a − 1) + (b − 1)]: the N × 4 array
// of the thesis walkthrough (4.5, ComparePlanes).
using KeyPointOffsets = std::array<Eigen::Vector2d, 4>;

// The four series of Rule 13 over observations `first[i]`, `second[i]` of the same iteration
// (equal sizes; invalid_argument otherwise). Empty input gives samples = 0. With
// `rotate_to_first` false (Rule 3 off) the offsets are the raw differences m₂ − m₁ (Fig 66).
// `offsets`, when given, receives the series themselves (key_point_offset's values, each assumed
// midpoint computed once per iteration), for a caller that judges them further.
KeyPointPairs key_point_pairs(std::span<const PlaneObject> first, std::span<const PlaneObject> second,
                              bool rotate_to_first = true, std::vector<KeyPointOffsets>* offsets = nullptr);

// Beyond the thesis (relative_plane.open_cut_ends): the σ of a pair whose ends the sensor cut in every
// sample (PlaneObject::a_cut, b_cut). Rule 13 picks the pair of ends that stayed put; an end cut
// by the field of view stays put relative to another cut end whenever both slide with the robot
// (two parallel walls while it drives straight), so a pair of cut ends can look static and name
// the wrong key points — the map is then built a piece's length off, and every check against it
// agrees. Only ends the sensor saw as the wall's own can be key points.
inline constexpr double kCutEndSigma = 1e9;

// Each pair's mean and σ of `pairs` taken again over the samples in which neither of its two
// ends was cut; a pair with fewer than `min_samples` such samples gets σ = kCutEndSigma.
// `offsets`: key_point_pairs' series over `first`, `second`.
void restrict_to_real_ends(std::span<const PlaneObject> first, std::span<const PlaneObject> second,
                           std::span<const KeyPointOffsets> offsets, int min_samples, KeyPointPairs& pairs);

// What the pair with the lowest σ says (thesis 4.3.4).
struct KeyPointChoice {
  // The pair whose mean is `delta`: the lowest σ. Its ends are the key points unless the plane
  // is static (either end serves) or the pair is ambiguous.
  KeyPoint anchor1 = KeyPoint::Left;
  KeyPoint anchor2 = KeyPoint::Left;
  KeyPoint key_point1 = KeyPoint::None;  // Rule 14: None when no end is known to be the static one
  KeyPoint key_point2 = KeyPoint::None;
  // The plane's two assumed midpoints behaved alike: it did not change size in the interval, so
  // its length is its size there and no key point is needed (thesis 4.3.4).
  bool static1 = false;
  bool static2 = false;
  // Rule 15: the two diagonal pairs tie low while the mixed ones are high — two parallel planes
  // growing or shrinking together. Both key points are None; the offset is right for symmetric
  // planes (hallway), wrong by one diagonal for the collinear shrink + grow of Fig 97 [T] — which
  // the distance test (KeyPointTies::collinear_distance) decides instead when it can.
  bool ambiguous = false;
  bool collinear_tie_broken = false;  // the distance test chose the diagonal
  PlanarPose delta;  // pairs.delta(anchor1, anchor2), in every case (thesis 4.3.4)
};

// The mean distance between key point a of the first plane and key point b of the second over
// the pairs' interval, from pair (a, b)'s mean offset (offsets in the first plane's frame, Rule 3).
double key_point_distance(const KeyPointPairs& pairs, KeyPoint a, KeyPoint b);

// Rules 13 and 15 on the four spreads: the lowest σ gives the offset; the diagonal tie is
// checked first (ambiguous, unless the collinear distance test decides it), then each plane on
// its own — a plane whose two ends give close σ against the other plane's chosen end is static.
// The distance test needs the offsets in the first plane's frame (`rotated`, Rule 3).
KeyPointChoice choose_key_points(const KeyPointPairs& pairs, const KeyPointTies& ties, bool rotated = true);

}  // namespace relslam::plane
