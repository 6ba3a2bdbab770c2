#include "relslam/em/tight_refit.hpp"

#include <algorithm>
#include <cmath>

namespace relslam::em {
namespace {

// 1.4826 · median |x|: the standard deviation of normal residuals, unmoved by up to half of
// them being outliers.
constexpr double kMadToSigma = 1.4826;

double median_of(std::vector<double> values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

void residuals_of(const Eigen::Vector3d& normal, double offset, const EmPlane& plane,
                  std::span<const Eigen::Vector3d> points, std::vector<double>& r) {
  r.clear();
  for (int i : plane.points) r.push_back(std::abs(normal.dot(points[static_cast<std::size_t>(i)]) + offset));
}

// One gate round on one plane; the points removed (0: the plane is left as it was). The
// residuals are taken from the fit of the plane's better half (the points at most the median
// residual from it): the neighbour's points tilt the full fit, so that its own points' residuals
// grow towards theirs, but they are a minority and fall in the worse half.
int gate_once(EmPlane& plane, std::span<const Eigen::Vector3d> points, const EmOptions& o, std::vector<double>& r) {
  residuals_of(plane.normal, plane.offset, plane, points, r);
  const double half_gate = median_of(r);
  std::vector<int> better;
  for (std::size_t k = 0; k < r.size(); ++k)
    if (r[k] <= half_gate) better.push_back(plane.points[k]);
  const std::optional<PlaneFit> core = fit_plane(points, better);
  if (!core) return 0;
  residuals_of(core->normal, core->offset, plane, points, r);
  const double gate = std::max(o.refit_gate * kMadToSigma * median_of(r), 1e-6 * o.inlier_distance);
  EmPlane next = plane;
  next.points.clear();
  for (std::size_t k = 0; k < r.size(); ++k)
    if (r[k] <= gate) next.points.push_back(plane.points[k]);
  const int removed = static_cast<int>(plane.points.size() - next.points.size());
  if (removed == 0 || !refit(next, points)) return 0;
  plane = std::move(next);
  return removed;
}

}  // namespace

int tight_refit(std::vector<EmPlane>& planes, std::span<const Eigen::Vector3d> points, const EmOptions& o) {
  if (!(o.refit_gate > 0.0)) return 0;
  int removed = 0;
  std::vector<double> residuals;
  for (EmPlane& plane : planes) {
    if (plane.points.size() < 3) continue;
    for (int round = 0; round < o.refit_rounds; ++round) {
      const int gone = gate_once(plane, points, o, residuals);
      if (gone == 0) break;
      removed += gone;
    }
  }
  return removed;
}

}  // namespace relslam::em
