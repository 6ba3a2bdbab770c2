#include "relslam/sim/figure_eight.hpp"

#include <cmath>
#include <numbers>

namespace relslam::sim {
namespace {

constexpr double kPi = std::numbers::pi;
// Half angle between the two crossing tangents: asin(r / c) with centre distance c = 2r.
constexpr double kTangentAngle = kPi / 6.0;

// Top-view pose: position (X, Y) and heading psi (counter-clockwise from +X).
struct TopView {
  double x, y, psi;
};

TopView straight(double x0, double y0, double psi, double t) {
  return {x0 + t * std::cos(psi), y0 + t * std::sin(psi), psi};
}

// Arc around (cx, cy) starting at polar angle alpha0; sign +1 counter-clockwise, -1 clockwise.
TopView arc(double cx, double cy, double r, double alpha0, double sign, double t) {
  const double alpha = alpha0 + sign * t / r;
  return {cx + r * std::cos(alpha), cy + r * std::sin(alpha), alpha + sign * kPi / 2.0};
}

}  // namespace

FigureEight::FigureEight(double loop_length, double incline_height)
    : length_(loop_length), incline_height_(incline_height) {
  const double turn = kPi + 2.0 * kTangentAngle;
  radius_ = loop_length / (2.0 * turn + 4.0 * std::sqrt(3.0));
  straight_ = std::sqrt(3.0) * radius_;
  arc_ = radius_ * turn;
}

CenterlinePoint FigureEight::at(double s) const {
  s = std::fmod(s, length_);
  if (s < 0) s += length_;
  const double r = radius_, c = 2.0 * radius_, l = straight_;
  const double down_right = -kTangentAngle, down_left = kPi + kTangentAngle;

  // Six pieces: out to the right circle, round it, back to the crossing, out to the left
  // circle, round it, back to the crossing.
  TopView v{};
  double t = s;
  if (t < l) {
    v = straight(0, 0, down_right, t);
  } else if ((t -= l) < arc_) {
    v = arc(c, 0, r, -(kPi / 2 + kTangentAngle), +1, t);
  } else if ((t -= arc_) < l) {
    v = straight(c - r * std::sin(kTangentAngle), r * std::cos(kTangentAngle), down_left, t);
  } else if ((t -= l) < l) {
    v = straight(0, 0, down_left, t);
  } else if ((t -= l) < arc_) {
    v = arc(-c, 0, r, -kPi / 2 + kTangentAngle, -1, t);
  } else {
    t -= arc_;
    v = straight(-c + r * std::sin(kTangentAngle), r * std::cos(kTangentAngle), down_right, t);
  }

  const double phase = 2.0 * kPi * s / length_;
  const double height = incline_height_ * (1.0 - std::cos(phase)) / 2.0;
  const double slope = incline_height_ * kPi / length_ * std::sin(phase);  // dh/ds

  // Top view (X, Y) -> design frame (x, y, z) = (X, height, -Y).
  CenterlinePoint p;
  p.position = {v.x, height, -v.y};
  const Eigen::Vector3d horizontal(std::cos(v.psi), 0.0, -std::sin(v.psi));
  p.tangent = (horizontal + slope * Eigen::Vector3d::UnitY()).normalized();
  p.left = Eigen::Vector3d(-std::sin(v.psi), 0.0, -std::cos(v.psi));
  return p;
}

}  // namespace relslam::sim
