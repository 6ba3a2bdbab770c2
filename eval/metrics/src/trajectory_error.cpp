#include "relslam/eval/metrics/trajectory_error.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace relslam::eval {

TrajectoryError trajectory_error(const std::vector<Rigid3>& estimate, const std::vector<Rigid3>& truth) {
  TrajectoryError e;
  const std::size_t n = std::min(estimate.size(), truth.size());
  if (n == 0) return e;
  Eigen::Matrix3Xd est(3, static_cast<Eigen::Index>(n)), tru(3, static_cast<Eigen::Index>(n));
  double sum = 0;
  for (std::size_t k = 0; k < n; ++k) {
    est.col(static_cast<Eigen::Index>(k)) = estimate[k].translation;
    tru.col(static_cast<Eigen::Index>(k)) = truth[k].translation;
    sum += (estimate[k].translation - truth[k].translation).squaredNorm();
  }
  e.ate_rmse = std::sqrt(sum / static_cast<double>(n));
  if (n >= 3) {
    const Eigen::Matrix4d align = Eigen::umeyama(est, tru, false);  // truth_T_estimate
    const Eigen::Matrix3Xd moved = (align.topLeftCorner<3, 3>() * est).colwise() + align.topRightCorner<3, 1>();
    e.ate_rmse_aligned = std::sqrt((moved - tru).colwise().squaredNorm().sum() / static_cast<double>(n));
  } else {
    e.ate_rmse_aligned = e.ate_rmse;
  }
  double t2 = 0, r2 = 0;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const Rigid3 moved_true = truth[k].inverse() * truth[k + 1];
    const Rigid3 moved_est = estimate[k].inverse() * estimate[k + 1];
    const Rigid3 error = moved_true.inverse() * moved_est;
    t2 += error.translation.squaredNorm();
    const double angle = Eigen::AngleAxisd(error.rotation).angle() * 180.0 / std::numbers::pi;
    r2 += angle * angle;
  }
  if (n > 1) {
    e.rpe_translation_rmse = std::sqrt(t2 / static_cast<double>(n - 1));
    e.rpe_rotation_rmse_deg = std::sqrt(r2 / static_cast<double>(n - 1));
  }
  return e;
}

}  // namespace relslam::eval
