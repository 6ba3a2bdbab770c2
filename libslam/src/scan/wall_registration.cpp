#include "relslam/scan/wall_registration.hpp"

#include "relslam/scan/segment_stability.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <optional>

namespace relslam::scan {
namespace {

struct Pair {
  const PlaneObject* previous;
  const PlaneObject* current;
};

// The previous wall nearest to `moved` (the current wall in the previous frame) within the
// bounds, if any.
std::optional<Pair> partner(const std::vector<PlaneObject>& previous, const PlaneObject& moved,
                            const PlaneObject& current, double max_offset, double max_angle) {
  std::optional<Pair> best;
  double best_offset = std::numeric_limits<double>::infinity();
  for (const PlaneObject& p : previous) {
    if (p.normal().dot(moved.normal()) < std::cos(max_angle)) continue;
    const double offset = std::abs(p.normal().dot(moved.midpoint()) + p.offset());
    if (offset > max_offset || offset >= best_offset || overlap(p, moved) <= 0) continue;
    best_offset = offset;
    best = Pair{&p, &current};
  }
  return best;
}

// One Gauss-Newton step on (dx, dz, dψ), applied on the left (in the previous frame): each
// pair's two current ends against the previous wall's line. Along the directions the walls
// measure less well than the guess (the prior's weight; along a corridor: not at all) the step
// goes back to the guess instead, so the guess biases nothing the walls do measure.
PlanarPose refined(const std::vector<Pair>& pairs, const PlanarPose& estimate, const PlanarPose& guess,
                   const WallRegistrationOptions& o, double& rms) {
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  double sum = 0;
  const double w_line = 1.0 / (o.sigma_line * o.sigma_line);
  for (const Pair& pr : pairs)
    for (const Eigen::Vector2d& end : {pr.current->a, pr.current->b}) {
      const Eigen::Vector2d q = estimate * end;
      const Eigen::Vector2d n = pr.previous->normal();
      const double r = n.dot(q) + pr.previous->offset();
      const Eigen::Vector3d j(n.x(), n.y(), n.dot(Eigen::Vector2d(-q.y(), q.x())));
      h += w_line * j * j.transpose();
      g += w_line * j * r;
      sum += r * r;
    }
  rms = pairs.empty() ? 0.0 : std::sqrt(sum / (2.0 * static_cast<double>(pairs.size())));
  // The update that would move the estimate back to the guess (to first order).
  const double dpsi = wrap_angle(guess.heading - estimate.heading);
  const Eigen::Vector2d turned = planar_rotation(dpsi) * estimate.translation;
  const Eigen::Vector3d to_guess(guess.translation.x() - turned.x(), guess.translation.y() - turned.y(), dpsi);
  // Eigen-directions of H in units where the prior's weights are 1.
  const Eigen::Vector3d scale(o.prior_sigma_translation, o.prior_sigma_translation, o.prior_sigma_heading_rad);
  const Eigen::Matrix3d hs = scale.asDiagonal() * h * scale.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(hs);
  const Eigen::Vector3d gs = scale.asDiagonal() * g;
  const Eigen::Vector3d guess_s = scale.cwiseInverse().asDiagonal() * to_guess;
  Eigen::Vector3d ds = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d v = eig.eigenvectors().col(k);
    const double lambda = eig.eigenvalues()(k);
    ds += v * (lambda > 1.0 ? -v.dot(gs) / lambda : v.dot(guess_s));
  }
  const Eigen::Vector3d d = scale.asDiagonal() * ds;
  return PlanarPose::from(d(0), d(1), d(2)) * estimate;
}

}  // namespace

WallRegistration register_walls(const std::vector<PlaneObject>& previous, const std::vector<PlaneObject>& current,
                                const PlanarPose& guess, const WallRegistrationOptions& options) {
  WallRegistration out{guess, 0, false, 0};
  PlanarPose estimate = guess;
  std::vector<Pair> pairs;
  for (int it = 0; it < options.iterations; ++it) {
    const double f = options.iterations > 1 ? static_cast<double>(it) / (options.iterations - 1) : 1.0;
    const double max_offset = options.max_offset + f * (options.final_offset - options.max_offset);
    const double max_angle = options.max_angle_rad + f * (options.final_angle_rad - options.max_angle_rad);
    pairs.clear();
    for (const PlaneObject& c : current)
      if (auto p = partner(previous, c.transformed(estimate), c, max_offset, max_angle)) pairs.push_back(*p);
    if (static_cast<int>(pairs.size()) < options.min_pairs) return out;
    estimate = refined(pairs, estimate, guess, options, out.rms);
  }
  out.previous_T_current = estimate;
  out.pairs = static_cast<int>(pairs.size());
  out.used = true;
  return out;
}

}  // namespace relslam::scan
