#include "relslam/core/planar_pose.hpp"

#include <cmath>
#include <numbers>

namespace relslam {

double wrap_angle(double angle_rad) {
  double a = std::remainder(angle_rad, 2.0 * std::numbers::pi);  // [−π, π]
  if (a <= -std::numbers::pi) a += 2.0 * std::numbers::pi;       // −π belongs to +π
  return a;
}

Eigen::Matrix2d planar_rotation(double angle_rad) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  Eigen::Matrix2d r;
  r << c, -s, s, c;
  return r;
}

Rigid3 rigid_from_planar(const PlanarPose& pose, double y) {
  return {rotation_about(-Eigen::Vector3d::UnitY(), pose.heading),
          Eigen::Vector3d(pose.translation.x(), y, pose.translation.y())};
}

}  // namespace relslam
