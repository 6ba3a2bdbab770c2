#include "relslam/point/rlt_icp.hpp"

#include <Eigen/Geometry>
#include <Eigen/SVD>

namespace relslam::point {
namespace {

// Second singular value below this share of the first: the points lie on a line [C].
constexpr double kCollinear = 1e-9;
// Two points closer than this (units) give no line [C]: far below any sensor noise.
constexpr double kCoincident = 1e-9;

}  // namespace

std::optional<Rigid3> rlt_icp(std::span<const Eigen::Vector3d> a, std::span<const Eigen::Vector3d> b) {
  if (a.size() != b.size() || a.size() < 3) return std::nullopt;
  Eigen::Vector3d mean_a = Eigen::Vector3d::Zero(), mean_b = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < a.size(); ++i) {
    mean_a += a[i];
    mean_b += b[i];
  }
  mean_a /= static_cast<double>(a.size());
  mean_b /= static_cast<double>(b.size());
  // The cross-covariance column by column: the very sums of h += da * db^T (each element adds
  // da(r) * db(c) in pair order), with the nine accumulators in registers, not in memory.
  Eigen::Vector3d h0 = Eigen::Vector3d::Zero(), h1 = Eigen::Vector3d::Zero(), h2 = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Eigen::Vector3d da = a[i] - mean_a, db = b[i] - mean_b;
    h0 += da * db.x();
    h1 += da * db.y();
    h2 += da * db.z();
  }
  Eigen::Matrix3d h;
  h << h0, h1, h2;

  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector3d s = svd.singularValues();
  if (!(s[0] > 0) || s[1] < kCollinear * s[0]) return std::nullopt;
  const Eigen::Matrix3d& u = svd.matrixU();
  const Eigen::Matrix3d& v = svd.matrixV();
  // Reflection fix: a proper rotation even when the best orthogonal fit is a mirror, which
  // happens for planar sets (the third singular vector's sign is then arbitrary).
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (v * u.transpose()).determinant() < 0 ? -1.0 : 1.0;
  Rigid3 b_T_a;
  b_T_a.rotation = v * d * u.transpose();
  b_T_a.translation = mean_b - b_T_a.rotation * mean_a;
  return b_T_a;
}

std::optional<Rigid3> register_two_points(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1,
                                          const Eigen::Vector3d& b0, const Eigen::Vector3d& b1,
                                          const Eigen::Matrix3d& prior_b_R_a, const Eigen::Vector3d& b_up,
                                          double max_line_sine) {
  const Eigen::Vector3d line_a = a1 - a0, line_b = b1 - b0;
  if (!(line_a.norm() > kCoincident) || !(line_b.norm() > kCoincident)) return std::nullopt;
  const Eigen::Vector3d u_b = line_b.normalized();
  if (std::abs(u_b.dot(b_up)) > max_line_sine) return std::nullopt;
  const Eigen::Vector3d u_prior = prior_b_R_a * line_a.normalized();
  Rigid3 b_T_a;
  b_T_a.rotation = Eigen::Quaterniond::FromTwoVectors(u_prior, u_b).toRotationMatrix() * prior_b_R_a;
  b_T_a.translation = 0.5 * (b0 + b1) - b_T_a.rotation * (0.5 * (a0 + a1));
  return b_T_a;
}

Rigid3 register_one_point(const Eigen::Vector3d& a0, const Eigen::Vector3d& b0, const Eigen::Matrix3d& b_R_a) {
  Rigid3 b_T_a;
  b_T_a.rotation = b_R_a;
  b_T_a.translation = b0 - b_R_a * a0;
  return b_T_a;
}

Rigid3 register_centroids(std::span<const Eigen::Vector3d> a, std::span<const Eigen::Vector3d> b,
                          const Eigen::Matrix3d& b_R_a) {
  Eigen::Vector3d mean_a = Eigen::Vector3d::Zero(), mean_b = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < a.size(); ++i) {
    mean_a += a[i];
    mean_b += b[i];
  }
  const double n = static_cast<double>(a.size());
  return register_one_point(mean_a / n, mean_b / n, b_R_a);
}

Eigen::Matrix3d interpolate_rotation(const Eigen::Matrix3d& from, const Eigen::Matrix3d& to, double weight) {
  return Eigen::Quaterniond(from).slerp(weight, Eigen::Quaterniond(to)).toRotationMatrix();
}

Eigen::Matrix3d mean_rotation(const Eigen::Matrix3d& sum) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(sum, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1.0 : 1.0;
  return svd.matrixU() * d * svd.matrixV().transpose();
}

}  // namespace relslam::point
