// Line placement's evidence from each checked pose (line_placement_control.hpp).

#include "line_placement_control.hpp"

#include "pose_check_control.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>

namespace relslam::plane {
namespace {

// The pose putting every seen plane on its map plane's line (the heading their mean direction
// difference) across the lines' main direction, and along it keeping the seen planes' centre
// where `held` puts it. Only the main direction: planes within min_angle of each other fix the
// position along them only through their small angle, which the noise decides.
PlanarPose fit_pose_holding(std::span<const LinePair> pairs, const PlanarPose& held) {
  double c = 0, s = 0;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const LinePair& p : pairs) {
    c += std::cos(p.mapped.angle() - p.seen.angle());
    s += std::sin(p.mapped.angle() - p.seen.angle());
    centre += p.seen.midpoint() / static_cast<double>(pairs.size());
  }
  const double heading = std::atan2(s, c);
  const Eigen::Matrix2d rotation = planar_rotation(heading);
  const Eigen::Vector2d t0 = held * centre - rotation * centre;
  Eigen::Matrix2d a = Eigen::Matrix2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  for (const LinePair& p : pairs) {
    const Eigen::Vector2d n = p.mapped.normal();  // n·(R m_seen + t) + d = 0 on the map line
    a += n * n.transpose();
    b += n * (-p.mapped.offset() - n.dot(rotation * p.seen.midpoint()));
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> main(a);  // eigenvalues ascending
  const Eigen::Vector2d v = main.eigenvectors().col(1);
  return PlanarPose{t0 + v * v.dot(b - a * t0) / main.eigenvalues()(1), wrap_angle(heading)};
}

}  // namespace

bool hold_along(RltXPointsState& s, const RltXPointsScratch& in, const IntegrityOptions& options,
                const PlanarPose& world_T_start) {
  const int gap = s.iteration_ - s.last_valid_iteration_;
  if (s.checked_pose_.valid || s.checked_pose_.reason != PoseReason::OneDirection || !s.last_valid_pose_.valid ||
      gap > options.continuity_window)
    return false;
  const std::vector<LinePair> pairs = line_pairs(s, in);
  if (pairs.empty()) return false;
  const PlanarPose pose = fit_pose_holding(pairs, world_T_start);
  if (!within_reach(pose, s.last_valid_pose_.world_T_robot, gap, options) ||
      !std::ranges::all_of(pairs, [&](const LinePair& p) { return agrees(p, pose, options); }))
    return false;
  s.checked_pose_ = {pose, true, static_cast<int>(pairs.size()), PoseReason::MotionModel};
  s.pose_ = s.checked_pose_;
  s.last_valid_pose_ = s.pose_;
  s.last_valid_iteration_ = s.iteration_;
  s.no_pose_count_ = 0;
  return true;
}


void gather_line_evidence(RltXPointsState& s, const RltXPointsScratch& in, const LinePlacementOptions& options,
                          bool held) {
  s.line_map_.resize(s.planes_.size());
  // Only a pose the walls' lines fixed, or held along parallel ones: the motion model's track
  // guesses the motion along its one plane from a model (Rules 23-25), and a relocalised pose is
  // a find against the map, not a scan's walls.
  if (!s.checked_pose_.valid || (s.checked_pose_.reason != PoseReason::Lines && !held)) return;
  const std::vector<MapPlane>& map = s.builder_.map();
  for (std::size_t i = 0; i < in.stamped_.size(); ++i) {
    const PlaneId p = in.assignment_[i];
    if (p == kNone) continue;
    LinePlacement& placement = s.line_map_[p];
    // A wall a group places is the group's; one the lines placed still grows along its line.
    if (!placement.placed && p < static_cast<PlaneId>(map.size()) && map[p].mapped) continue;
    add_line_evidence(placement, in.stamped_[i].transformed(s.checked_pose_.world_T_robot), options);
  }
}

}  // namespace relslam::plane
