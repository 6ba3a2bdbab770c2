#include "relslam/plane/rlt_xmm_point.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace relslam::plane {
namespace {

// MotionModelOptions::real_end_motion: the robot's motion between two observations of the plane,
// in the motion model's frame, from an end the sensor saw as the wall's own both times: that end
// E is fixed, p + Rot(ψ)·e = E at both, so p − p' = Rot(ψ')·e' − Rot(ψ)·e. None when each end
// was cut in one of the two.
std::optional<Eigen::Vector2d> real_end_motion(const PlaneObject& before, const PlaneObject& now, double psi_before,
                                               double psi_now) {
  const PlanarPose r_before{Eigen::Vector2d::Zero(), psi_before}, r_now{Eigen::Vector2d::Zero(), psi_now};
  if (!before.a_cut && !now.a_cut) return r_before * before.a - r_now * now.a;
  if (!before.b_cut && !now.b_cut) return r_before * before.b - r_now * now.b;
  return std::nullopt;
}

}  // namespace

RltXMMPoint::RltXMMPoint(XPointId xpoint, PlaneId plane, const PlanarPose& world_T_anchor, int start_iteration,
                         const PlaneObject& world_plane)
    : xpoint_(xpoint),
      plane_(plane),
      world_T_anchor_(world_T_anchor),
      start_iteration_(start_iteration),
      mm_T_plane_(world_T_anchor.inverse() * world_plane.pose()),
      start_min_(-0.5 * world_plane.length()),
      start_max_(0.5 * world_plane.length()),
      s_min_(start_min_),
      s_max_(start_max_) {}

void RltXMMPoint::compute(std::vector<RltPlane>& planes, const MotionModelOptions& options) {
  const RltPlane& p = planes[plane_];
  // The plane's axes in the motion model's frame: u along it (a → b), n its normal towards the
  // robot (the visible side).
  const Eigen::Vector2d m = mm_T_plane_.translation;
  const Eigen::Vector2d u(std::cos(mm_T_plane_.heading), std::sin(mm_T_plane_.heading));
  const Eigen::Vector2d n(-u.y(), u.x());
  const double theta_ref = mm_T_plane_.heading;
  const double cos_parallel = std::cos(options.parallel_angle_rad);
  // α: the robot's forward direction written in the plane's axes, f = cos α·(−n) + sin α·u.
  const auto alpha_of = [&](double psi) {
    const Eigen::Vector2d f(std::cos(psi), std::sin(psi));
    return std::atan2(f.dot(u), -f.dot(n));
  };

  track_.clear();
  s_min_ = start_min_;
  s_max_ = start_max_;
  bool grew_min = false, grew_max = false;
  along_observed_ = true;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // R(start) = identity [T, Rule 27]
  double previous_distance = 0, previous_alpha = 0;
  const PlaneObject* previous = nullptr;
  double previous_psi = 0;
  for (int i = p.lower_bound(start_iteration_); i < p.size(); ++i) {
    const PlaneObject& seen = p[i];
    if (ended() && seen.iteration > end_iteration_) break;
    // Rule 24: the heading from the plane's observed angle; the distance to it from the
    // point-to-plane equation.
    const double psi = wrap_angle(theta_ref - seen.angle());
    const double distance = seen.offset();
    const double alpha = alpha_of(psi);
    MotionModelSample sample{seen.iteration, {}, distance, 0, 0};
    if (!track_.empty()) {
      // Forward-only motion by s moves the robot s·cos α towards the plane and s·sin α along it.
      sample.delta_normal = previous_distance - distance;
      const double mean_alpha = std::atan2(std::sin(alpha) + std::sin(previous_alpha),
                                           std::cos(alpha) + std::cos(previous_alpha));
      // Rule 25: nearly parallel to the plane the along-plane part is noise; x motion only.
      const bool along_dropped = std::abs(std::cos(mean_alpha)) < cos_parallel;
      if (!along_dropped) sample.delta_tangent = sample.delta_normal * std::tan(mean_alpha);
      if (const std::optional<Eigen::Vector2d> moved =
              options.real_end_motion ? real_end_motion(*previous, seen, previous_psi, psi) : std::nullopt)
        sample.delta_tangent = moved->dot(u);
      else if (along_dropped && options.track_along)
        along_observed_ = false;
      position += sample.delta_normal * -n + sample.delta_tangent * u;
    }
    sample.mm_T_robot = {position, psi};
    // Rule 23 (ExpandPoints): the observed ends along the plane; an end that comes into view
    // beyond the known extent grows the plane.
    for (const Eigen::Vector2d& end : {seen.a, seen.b}) {
      const double s = u.dot(sample.mm_T_robot * end - m);
      if (s < s_min_ - options.grow_threshold) {
        s_min_ = s;
        grew_min = true;
      }
      if (s > s_max_ + options.grow_threshold) {
        s_max_ = s;
        grew_max = true;
      }
    }
    track_.push_back(sample);
    previous_distance = distance;
    previous_alpha = alpha;
    previous_psi = psi;
    previous = &seen;
  }

  fill_membership(planes, grew_min, grew_max);
}

void RltXMMPoint::fill_membership(std::vector<RltPlane>& planes, bool grew_min, bool grew_max) const {
  // The membership: the plane at its tracked extent; its key point is the end that did not move.
  const RltPlane& p = planes[plane_];
  RltXPointRef* ref = planes[plane_].ref(xpoint_);
  ref->valid = true;
  ref->tracked = true;
  ref->pose = mm_T_plane_ * PlanarPose{{0.5 * (s_min_ + s_max_), 0.0}, 0.0};
  ref->max_length = s_max_ - s_min_;
  ref->height = p.latest().height();
  ref->key_point = grew_max && !grew_min   ? KeyPoint::Left
                   : grew_min && !grew_max ? KeyPoint::Right
                                           : KeyPoint::None;
  // Without a moved end the extent is known as a whole (nothing grew, or both ends were seen):
  // the plane is placed without a key point.
  ref->size_static = ref->key_point == KeyPoint::None;
  if (!track_.empty()) ref->interval = {track_.front().iteration, track_.back().iteration};
  ref->samples = static_cast<int>(track_.size());
}

std::optional<PlanarPose> RltXMMPoint::world_T_robot(int iteration) const {
  if (track_.empty() || track_.back().iteration != iteration) return std::nullopt;
  return world_T_anchor_ * track_.back().mm_T_robot;
}

}  // namespace relslam::plane
