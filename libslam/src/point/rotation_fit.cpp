#include "relslam/point/rotation_fit.hpp"

#include <Eigen/Geometry>

namespace relslam::point {

std::optional<Eigen::Matrix3d> fitted_rotation(std::span<const std::pair<int, Eigen::Matrix3d>> rotations, int at) {
  if (rotations.size() < 3) return std::nullopt;
  const Eigen::Matrix3d& reference = rotations.front().second;
  // Least squares v(t) = a + b (t - at), per component: the normal equations of a line.
  double n = 0, st = 0, stt = 0;
  Eigen::Vector3d sv = Eigen::Vector3d::Zero(), stv = Eigen::Vector3d::Zero();
  for (const auto& [t, rotation] : rotations) {
    const Eigen::AngleAxisd turned(reference.transpose() * rotation);
    const Eigen::Vector3d v = turned.angle() * turned.axis();
    const double dt = static_cast<double>(t - at);
    n += 1;
    st += dt;
    stt += dt * dt;
    sv += v;
    stv += dt * v;
  }
  const double det = n * stt - st * st;
  if (!(det > 0)) return std::nullopt;  // a single iteration repeated
  const Eigen::Vector3d a = (stt * sv - st * stv) / det;
  const double angle = a.norm();
  if (!(angle > 0)) return reference;
  return Eigen::Matrix3d(reference * Eigen::AngleAxisd(angle, a / angle).toRotationMatrix());
}

}  // namespace relslam::point
