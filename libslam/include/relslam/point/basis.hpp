#pragma once
// The three-point basis of an RltGroup (thesis 6.3.3, Fig 109) and its selection (6.5.4).

#include <Eigen/Core>

#include <array>
#include <optional>
#include <string_view>
#include <vector>

namespace relslam::point {

// Coordinates relative to three basis points: B0 at the origin, B1 on the negative x axis,
// B2 in the xz plane with z > 0 (thesis 6.3.3). The frame depends only on the three points, so
// coordinates computed from any viewpoint agree: the invariance the group averages rely on.
struct BasisFrame {
  Eigen::Matrix3d rotation;  // rows ex, ey, ez
  Eigen::Vector3d origin;    // B0
  Eigen::Vector3d operator()(const Eigen::Vector3d& p) const { return rotation * (p - origin); }
};

// Nothing when B0 and B1 nearly coincide or B2 is nearly on their line (relative tolerance
// `epsilon` of |B0 B1|): that iteration is skipped rather than averaged with a wild frame.
std::optional<BasisFrame> basis_frame(const Eigen::Vector3d& b0, const Eigen::Vector3d& b1, const Eigen::Vector3d& b2,
                                      double epsilon = 1e-6);

enum class BasisSelection {
  Farthest,    // thesis 6.5.4: farthest pair, then the point farthest from their line
  FirstThree,  // the first three members, the early version compared in Fig 119
};
std::string_view to_string(BasisSelection selection);  // "farthest", "first_three"

// Indices of (B0, B1, B2) among `positions`. Farthest: O(n^2) search for the farthest pair
// (B0 the earlier of the two), then O(n) for the point farthest from their line; nothing if
// that distance is below min_line_ratio·|B0 B1| (the set is nearly collinear) or n < 3.
std::optional<std::array<int, 3>> select_basis(const std::vector<Eigen::Vector3d>& positions, BasisSelection selection,
                                               double min_line_ratio);

}  // namespace relslam::point
