#include "clipped_wall_fixture.hpp"

namespace relslam::plane::test {

PlaneObject ClippedWall::part(double s0, double s1) const {
  const Eigen::Vector2d u = (b - a).normalized();
  return {a + s0 * u, a + s1 * u};
}

PlaneObject ClippedWall::anchored(double l, KeyPoint k) const {
  return k == KeyPoint::Left ? part(0, l) : part(length() - l, length());
}

std::function<double(int)> constant(double s) {
  return [s](int) { return s; };
}
std::function<double(int)> moving(double s0, double per_iteration) {
  return [=](int t) { return s0 + per_iteration * t; };
}

PlanarPose robot_at(int t) { return PlanarPose::from(0.05 * t, 0.02 * t, 0.01 * t); }

std::vector<PlaneObject> observe_clipped(const ClippedWall& wall, int first, int n, const ClipNoise& noise,
                                         relslam::test::SeededRandom& random) {
  std::vector<PlaneObject> seen;
  const Eigen::Vector2d centre = wall.part(0, wall.length()).midpoint();
  for (int t = first; t < first + n; ++t) {
    double s0 = wall.from(t), s1 = wall.to(t);
    if (s1 <= s0) continue;
    if (s0 > 0) s0 += noise.cut * random.gaussian();
    if (s1 < wall.length()) s1 += noise.cut * random.gaussian();
    // Rigid noise about the wall's centre: translate(centre + δ) ∘ rotate(ε) ∘ translate(−centre).
    const Eigen::Vector2d shift(noise.position * random.gaussian(), noise.position * random.gaussian());
    const PlanarPose moved = PlanarPose{centre + shift, 0.0} *
                             PlanarPose{{0, 0}, noise.rotation_rad * random.gaussian()} * PlanarPose{-centre, 0.0};
    PlaneObject part = wall.part(s0, s1).transformed(moved).transformed(robot_at(t).inverse());
    part.iteration = t;
    seen.push_back(part);
  }
  return seen;
}

PlanarPose anchored_delta(const ClippedWall& w1, double l1, KeyPoint k1, const ClippedWall& w2, double l2,
                          KeyPoint k2) {
  return w1.anchored(l1, k1).pose().inverse() * w2.anchored(l2, k2).pose();
}

}  // namespace relslam::plane::test
