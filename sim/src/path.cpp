#include "relslam/sim/path.hpp"

#include "relslam/sim/figure_eight.hpp"
#include "relslam/sim/straight_line.hpp"

#include <cmath>
#include <numbers>

namespace relslam::sim {
namespace {

// Robot axes from the direction of travel: +z forward along the tangent, +x left (horizontal),
// +y completing a right-handed frame; no roll.
Eigen::Matrix3d tangent_frame(const Eigen::Vector3d& forward) {
  const Eigen::Vector3d left = Eigen::Vector3d::UnitY().cross(forward).normalized();
  const Eigen::Vector3d up = forward.cross(left);
  Eigen::Matrix3d r;
  r << left, up, forward;
  return r;
}

}  // namespace

Path::Path(const SimOptions& o)
    : kind_(o.path),
      wobble_(o.wobble),
      iterations_(static_cast<int>(iteration_count(o))),
      step_(sim::step_length(o)),
      field_length_(sim::field_length(o)) {
  if (o.path == PathKind::FigureEight)
    line_ = std::make_unique<FigureEight>(scaled_loop_length(o), o.scale * o.incline_height);
  else
    line_ = std::make_unique<StraightLine>(field_length_);
  world_T_design_ = design_T_robot(0.0).inverse();
}

Path::Path(Path&&) noexcept = default;
Path& Path::operator=(Path&&) noexcept = default;
Path::~Path() = default;

double Path::arc_length(int k) const {
  switch (kind_) {
    case PathKind::FigureEight: return std::fmod(k * step_, line_->length());
    case PathKind::Line: return k * step_;
    case PathKind::Stationary: return 0.0;
  }
  return 0.0;
}

Rigid3 Path::design_T_robot(double s) const {
  const CenterlinePoint c = line_->at(s);
  Rigid3 pose{tangent_frame(c.tangent), c.position};
  if (wobble_) {
    // Roll about the forward axis and a pitch offset about the left axis, with periods that
    // do not divide each other, so every rotational degree of freedom changes [C].
    constexpr double kDeg = std::numbers::pi / 180.0;
    const double roll = 2.0 * kDeg * std::sin(2.0 * std::numbers::pi * s / 380.0);
    const double pitch = 1.0 * kDeg * std::sin(2.0 * std::numbers::pi * s / 570.0);
    pose.rotation = pose.rotation * rotation_about(Eigen::Vector3d::UnitZ(), roll) *
                    rotation_about(Eigen::Vector3d::UnitX(), pitch);
  }
  return pose;
}

Rigid3 Path::world_T_robot(int k) const {
  if (k == 0) return Rigid3::identity();  // exact, not merely within rounding
  return world_T_design_ * design_T_robot(arc_length(k));
}

CenterlinePoint Path::centerline(double s) const {
  CenterlinePoint c = line_->at(s);
  c.position = world_T_design_ * c.position;
  c.tangent = world_T_design_.rotation * c.tangent;
  c.left = world_T_design_.rotation * c.left;
  return c;
}

}  // namespace relslam::sim
