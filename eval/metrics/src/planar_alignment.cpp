#include "relslam/eval/metrics/planar_alignment.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace relslam::eval {

double PlanarAlignment::rotation_deg() const {
  return std::atan2(rotation(1, 0), rotation(0, 0)) * 180.0 / std::numbers::pi;
}

PlanarAlignment align_planar(const std::vector<Eigen::Vector2d>& from, const std::vector<Eigen::Vector2d>& to,
                             bool with_scale) {
  PlanarAlignment a;
  const std::size_t n = std::min(from.size(), to.size());
  if (n < 2) return a;
  Eigen::Matrix2Xd src(2, static_cast<Eigen::Index>(n)), dst(2, static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    src.col(static_cast<Eigen::Index>(i)) = from[i];
    dst.col(static_cast<Eigen::Index>(i)) = to[i];
  }
  const Eigen::Matrix3d t = Eigen::umeyama(src, dst, with_scale);
  const Eigen::Matrix2d sr = t.topLeftCorner<2, 2>();
  a.scale = std::sqrt(std::abs(sr.determinant()));
  a.rotation = sr / a.scale;
  a.translation = t.topRightCorner<2, 1>();
  a.pairs = static_cast<int>(n);
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = (a.apply(from[i]) - to[i]).norm();
    sum += r * r;
    a.max = std::max(a.max, r);
  }
  a.rmse = std::sqrt(sum / static_cast<double>(n));
  return a;
}

namespace {

int nearest(const Eigen::Vector2d& p, const std::vector<Eigen::Vector2d>& set, double& distance) {
  int best = -1;
  distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < set.size(); ++i)
    if (const double d = (set[i] - p).norm(); d < distance) distance = d, best = static_cast<int>(i);
  return best;
}

}  // namespace

MapComparison compare_maps(const std::vector<Eigen::Vector2d>& map, const std::vector<Eigen::Vector2d>& reference,
                           double gate, int rounds) {
  MapComparison c;
  c.landmarks = static_cast<int>(map.size());
  c.reference_landmarks = static_cast<int>(reference.size());
  PlanarAlignment alignment;  // identity: the maps share their start pose
  std::vector<Eigen::Vector2d> from, to;
  std::vector<double> residuals;
  for (int round = 0; round <= rounds; ++round) {
    std::vector<Eigen::Vector2d> moved;
    for (const Eigen::Vector2d& p : map) moved.push_back(alignment.apply(p));
    from.clear(), to.clear(), residuals.clear();
    for (std::size_t i = 0; i < moved.size(); ++i) {
      double d = 0, back = 0;
      const int j = nearest(moved[i], reference, d);
      // Mutual nearest neighbours only: a duplicate landmark cannot claim a partner twice.
      if (j < 0 || d > gate || nearest(reference[j], moved, back) != static_cast<int>(i)) continue;
      from.push_back(map[i]);
      to.push_back(reference[j]);
      residuals.push_back(d);
    }
    if (round == rounds || from.size() < 3) break;
    alignment = align_planar(from, to, true);
  }
  c.matched = static_cast<int>(residuals.size());
  c.alignment = alignment;
  if (!residuals.empty()) {
    double sum = 0;
    for (double r : residuals) sum += r * r;
    c.rms = std::sqrt(sum / static_cast<double>(residuals.size()));
    std::nth_element(residuals.begin(), residuals.begin() + static_cast<std::ptrdiff_t>(residuals.size() / 2),
                     residuals.end());
    c.median = residuals[residuals.size() / 2];
  }
  return c;
}

}  // namespace relslam::eval
