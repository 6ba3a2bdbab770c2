#pragma once
// Test-only clipped walls for the key-point tests: a wall of which the robot sees a
// scripted part that grows and shrinks as a frustum would cut it, observed from a moving,
// turning robot, with the plane sensor's noise. Exact geometry, so the truth of every offset
// and key point is known.

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"
#include "relslam/plane/plane_object.hpp"
#include "seeded_random.hpp"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace relslam::plane::test {

// A wall in the world (`a` to `b`, front normal Rot(+90°)(b − a)) of which the robot sees the
// part from `from(t)` to `to(t)`, distances along the wall from `a`: an end inside (0, length)
// is cut by the frustum, an end at 0 or length is the wall's real end.
struct ClippedWall {
  Eigen::Vector2d a, b;
  std::function<double(int)> from, to;

  double length() const { return (b - a).norm(); }
  // The world segment from s0 to s1 along the wall.
  PlaneObject part(double s0, double s1) const;
  // The part of length `l` from end k: the reference a comparison anchored on k describes.
  PlaneObject anchored(double l, KeyPoint k) const;
};

std::function<double(int)> constant(double s);
std::function<double(int)> moving(double s0, double per_iteration);  // s0 + per_iteration·t

// Per-observation noise of the plane sensor (thesis 4.3.3): the whole wall moved by a Gaussian
// translation and turned about its midpoint before it is clipped, and each frustum-cut end
// jittered along the wall (the frustum meets the moved wall elsewhere) — so the sizes are noisy.
struct ClipNoise {
  double position = 0;      // units, per axis
  double rotation_rad = 0;  // about the wall's midpoint
  double cut = 0;           // units, along the wall, cut ends only
};

// The robot drives and turns (so Rule 3 has something to undo): its pose at iteration t.
PlanarPose robot_at(int t);

// What the robot reports of `wall` at iterations first..first+n−1, in its own frame; iterations
// where the visible part is empty are left out.
std::vector<PlaneObject> observe_clipped(const ClippedWall& wall, int first, int n, const ClipNoise& noise,
                                         relslam::test::SeededRandom& random);

// The truth for pair (k1, k2): the second wall's part of length l2 from its end k2 in the frame
// of the first wall's part of length l1 from its end k1 (thesis 4.3.4).
PlanarPose anchored_delta(const ClippedWall& w1, double l1, KeyPoint k1, const ClippedWall& w2, double l2, KeyPoint k2);

}  // namespace relslam::plane::test
