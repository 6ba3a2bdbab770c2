#pragma once
// The M-step's plane fit: total least squares after [DrGe03] (thesis 3.5.2 step 7).
// Eigen only.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <span>

namespace relslam::em {

// n·p + d = 0 with |n| = 1, through the centroid of the fitted points.
struct PlaneFit {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();
  double offset = 0.0;  // d
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  // Eigenvalues of the scatter matrix, ascending: [0] is the sum of squared distances to the
  // plane, [1] and [2] measure the spread within it.
  Eigen::Vector3d eigenvalues = Eigen::Vector3d::Zero();
};

// The thesis's recipe: centroid c, scatter M = Σ (p − c)(p − c)ᵀ (the 3×N matrix times its
// transpose), and the normal is M's eigenvector of the smallest eigenvalue (for the symmetric
// M the SVD's singular vectors are its eigenvectors). The normal is turned towards the origin,
// the sensor (d >= 0), so a fit's sign never depends on the points' order. Nothing (no plane)
// for fewer than 3 points, non-finite points, or points with no plane of their own: all equal
// or collinear (the middle eigenvalue below 1e-12 of the largest). With `box`, the points' tight
// axis-aligned box is set in the same pass (also when there is no plane).
std::optional<PlaneFit> fit_plane(std::span<const Eigen::Vector3d> points, std::span<const int> indices,
                                  Eigen::AlignedBox3d* box = nullptr);

}  // namespace relslam::em
