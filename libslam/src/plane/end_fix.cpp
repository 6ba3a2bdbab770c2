// The pose from parallel planes and their real ends (end_fix.hpp).

#include "relslam/plane/end_fix.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace relslam::plane {
namespace {

// Two real ends at least [C]: one could be a wall's end the map holds a little off, or the
// frustum's cut the sensor did not flag; two that agree are the position along the walls.
constexpr int kMinEnds = 2;

// The heading that turns every seen plane onto its map plane: the circular mean.
double mean_heading(std::span<const EndPair> pairs) {
  double c = 0, s = 0;
  for (const EndPair& e : pairs) {
    const double delta = e.pair.mapped.angle() - e.pair.seen.angle();
    c += std::cos(delta);
    s += std::sin(delta);
  }
  return std::atan2(s, c);
}

// Where each real end seen uncut puts the robot along `u`, given the heading's rotation.
std::vector<double> along_shifts(std::span<const EndPair> pairs, const Eigen::Matrix2d& rotation, const Eigen::Vector2d& u) {
  std::vector<double> shifts;
  for (const EndPair& e : pairs) {
    const PlaneObject& seen = e.pair.seen;
    const PlaneObject& mapped = e.pair.mapped;
    if (e.a_real && !seen.a_cut) shifts.push_back(u.dot(mapped.a - rotation * seen.a));
    if (e.b_real && !seen.b_cut) shifts.push_back(u.dot(mapped.b - rotation * seen.b));
  }
  return shifts;
}

}  // namespace

IntegrityResult fit_pose_to_ends(std::span<const EndPair> pairs, const IntegrityOptions& options,
                                 const std::optional<std::pair<PlanarPose, int>>& previous) {
  IntegrityResult out;
  out.reason = PoseReason::OneDirection;
  if (pairs.empty()) return out;
  const double heading = mean_heading(pairs);
  const Eigen::Matrix2d rotation = planar_rotation(heading);
  const Eigen::Vector2d n = pairs.front().pair.mapped.normal(), u = pairs.front().pair.mapped.tangent();
  // Across the walls: n_i·(R m_i + t) + d_i = 0 for each, with n_i = ±n, least squares in t·n.
  double across = 0, weight = 0;
  for (const EndPair& e : pairs) {
    const Eigen::Vector2d ni = e.pair.mapped.normal();
    const double c = ni.dot(n);
    across += c * (-e.pair.mapped.offset() - ni.dot(rotation * e.pair.seen.midpoint()));
    weight += c * c;
  }
  const std::vector<double> shifts = along_shifts(pairs, rotation, u);
  if (static_cast<int>(shifts.size()) < kMinEnds) return out;
  double along = 0;
  for (const double s : shifts) along += s;
  along /= static_cast<double>(shifts.size());
  out.reason = PoseReason::Disagree;
  if (std::ranges::any_of(shifts, [&](double s) { return std::abs(s - along) > options.offset_bound; })) return out;
  const PlanarPose pose{(across / weight) * n + along * u, wrap_angle(heading)};
  if (!std::ranges::all_of(pairs, [&](const EndPair& e) { return agrees(e.pair, pose, options); })) return out;
  out.world_T_robot = pose;
  out.planes = static_cast<int>(pairs.size());
  out.valid = !previous || within_reach(pose, previous->first, previous->second, options);
  out.reason = out.valid ? PoseReason::Ends : PoseReason::Jump;
  return out;
}

}  // namespace relslam::plane
