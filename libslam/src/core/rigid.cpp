#include "relslam/core/rigid.hpp"

namespace relslam {

Eigen::Quaterniond Rigid3::quaternion() const {
  Eigen::Quaterniond q(rotation);
  q.normalize();
  // One sign per rotation (w >= 0), so written trajectories do not flip between q and -q.
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  return q;
}

Eigen::Matrix3d rotation_about(const Eigen::Vector3d& unit_axis, double angle_rad) {
  return Eigen::AngleAxisd(angle_rad, unit_axis).toRotationMatrix();
}

}  // namespace relslam
