#include "relslam/em/tls_fit.hpp"

#include <Eigen/Eigenvalues>

namespace relslam::em {
namespace {

// Collinear (or coincident) points: the in-plane spread of the second axis is this small a
// share of the first's. Far below any real wall (spacing² / length² ~ 1e-3) [C].
constexpr double kCollinear = 1e-12;

}  // namespace

std::optional<PlaneFit> fit_plane(std::span<const Eigen::Vector3d> points, std::span<const int> indices,
                                   Eigen::AlignedBox3d* box) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  if (box) {
    box->setEmpty();
    for (int i : indices) {
      const Eigen::Vector3d& p = points[static_cast<std::size_t>(i)];
      centroid += p;
      box->extend(p);
    }
  } else {
    for (int i : indices) centroid += points[static_cast<std::size_t>(i)];
  }
  if (indices.size() < 3) return std::nullopt;
  centroid /= static_cast<double>(indices.size());
  if (!centroid.allFinite()) return std::nullopt;
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (int i : indices) {
    const Eigen::Vector3d q = points[static_cast<std::size_t>(i)] - centroid;
    scatter.noalias() += q * q.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
  if (solver.info() != Eigen::Success) return std::nullopt;
  PlaneFit fit;
  fit.eigenvalues = solver.eigenvalues();
  if (!(fit.eigenvalues[2] > 0.0) || fit.eigenvalues[1] <= kCollinear * fit.eigenvalues[2]) return std::nullopt;
  fit.normal = solver.eigenvectors().col(0).normalized();
  fit.centroid = centroid;
  fit.offset = -fit.normal.dot(centroid);
  if (fit.offset < 0.0) {
    fit.normal = -fit.normal;
    fit.offset = -fit.offset;
  }
  return fit;
}

}  // namespace relslam::em
