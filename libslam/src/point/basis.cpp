#include "relslam/point/basis.hpp"

#include <Eigen/Geometry>

namespace relslam::point {

std::string_view to_string(BasisSelection selection) {
  return selection == BasisSelection::Farthest ? "farthest" : "first_three";
}

std::optional<BasisFrame> basis_frame(const Eigen::Vector3d& b0, const Eigen::Vector3d& b1, const Eigen::Vector3d& b2,
                                      double epsilon) {
  const Eigen::Vector3d x_axis = b0 - b1;  // B1 lands on the negative x axis
  const double length = x_axis.norm();
  if (!(length > epsilon)) return std::nullopt;
  const Eigen::Vector3d ex = x_axis / length;
  const Eigen::Vector3d v = b2 - b0;
  const Eigen::Vector3d w = v - v.dot(ex) * ex;  // B2's offset from the B0-B1 line
  const double height = w.norm();
  if (!(height > epsilon * length)) return std::nullopt;
  const Eigen::Vector3d ez = w / height;  // B2 in the xz plane with z > 0
  const Eigen::Vector3d ey = ez.cross(ex);
  BasisFrame frame;
  frame.rotation.row(0) = ex;
  frame.rotation.row(1) = ey;
  frame.rotation.row(2) = ez;
  frame.origin = b0;
  return frame;
}

std::optional<std::array<int, 3>> select_basis(const std::vector<Eigen::Vector3d>& p, BasisSelection selection,
                                               double min_line_ratio) {
  const int n = static_cast<int>(p.size());
  if (n < 3) return std::nullopt;
  if (selection == BasisSelection::FirstThree) {
    if (!basis_frame(p[0], p[1], p[2], min_line_ratio)) return std::nullopt;
    return std::array<int, 3>{0, 1, 2};
  }
  int i0 = 0, i1 = 1;
  double best = -1;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (const double d = (p[i] - p[j]).squaredNorm(); d > best) best = d, i0 = i, i1 = j;
  const Eigen::Vector3d direction = (p[i1] - p[i0]).normalized();
  int i2 = -1;
  double farthest = -1;
  for (int i = 0; i < n; ++i) {
    if (i == i0 || i == i1) continue;
    const Eigen::Vector3d v = p[i] - p[i0];
    if (const double d = (v - v.dot(direction) * direction).squaredNorm(); d > farthest) farthest = d, i2 = i;
  }
  if (!(std::sqrt(farthest) >= min_line_ratio * std::sqrt(best))) return std::nullopt;
  return std::array<int, 3>{i0, i1, i2};
}

}  // namespace relslam::point
