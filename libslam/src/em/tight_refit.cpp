#include "relslam/em/tight_refit.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace relslam::em {
namespace {

// 1.4826 · median |x|: the standard deviation of normal residuals, unmoved by up to half of
// them being outliers.
constexpr double kMadToSigma = 1.4826;

// Buffers reused over the planes and rounds: a full frame's plane holds ~10⁵ points, and fresh
// vectors of that size cost more than the passes over them.
struct Scratch {
  std::vector<double> residuals, selection;
  std::vector<int> kept;
  std::vector<std::uint32_t> histogram;
};

// The median (the element of rank size / 2) of non-negative values, exactly as nth_element
// gives it but without sorting them all: the bit patterns of non-negative doubles order like
// the values, so one pass counting their top 16 bits (sign, exponent, 4 bits of mantissa) finds
// the bucket that holds the median, and only that bucket's few values are selected among
// (nth_element over 10⁵ residuals was the largest cost of a full frame's refit).
double median_of(const std::vector<double>& values, Scratch& s) {
  const std::size_t rank = values.size() / 2;
  s.histogram.assign(std::size_t{1} << 16, 0);
  for (double v : values) ++s.histogram[std::bit_cast<std::uint64_t>(v) >> 48];
  std::uint64_t bucket = 0;
  std::size_t below = 0;
  while (below + s.histogram[bucket] <= rank) below += s.histogram[bucket++];
  s.selection.clear();
  for (double v : values)
    if (std::bit_cast<std::uint64_t>(v) >> 48 == bucket) s.selection.push_back(v);
  const auto middle = s.selection.begin() + static_cast<std::ptrdiff_t>(rank - below);
  std::nth_element(s.selection.begin(), middle, s.selection.end());
  return *middle;
}

// |residual| of each point, in units of d_in at the point relative to d_in where d_in grows
// with the range (EmOptions::inlier_per_range2): a far point's larger noise then weighs as a
// near point's, and the median and gate below stay those of one noise level.
void residuals_of(const Eigen::Vector3d& normal, double offset, const EmPlane& plane,
                  std::span<const Eigen::Vector3d> points, const EmOptions& o, std::vector<double>& r) {
  r.resize(plane.points.size());
  for (std::size_t k = 0; k < r.size(); ++k) {
    const Eigen::Vector3d& p = points[static_cast<std::size_t>(plane.points[k])];
    r[k] = std::abs(normal.dot(p) + offset);
    if (o.inlier_per_range2 > 0.0) r[k] *= o.inlier_distance / inlier_distance_at(o, p);
  }
}

// The points of `plane` whose residual is at most `gate`, into `kept`.
void keep_within(const EmPlane& plane, const std::vector<double>& r, double gate, std::vector<int>& kept) {
  kept.clear();
  for (std::size_t k = 0; k < r.size(); ++k)
    if (r[k] <= gate) kept.push_back(plane.points[k]);
}

// One gate round on one plane; the points removed (0: the plane is left as it was). The
// residuals are taken from the fit of the plane's better half (the points at most the median
// residual from it): the neighbour's points tilt the full fit, so that its own points' residuals
// grow towards theirs, but they are a minority and fall in the worse half.
int gate_once(EmPlane& plane, std::span<const Eigen::Vector3d> points, const EmOptions& o, Scratch& s) {
  residuals_of(plane.normal, plane.offset, plane, points, o, s.residuals);
  keep_within(plane, s.residuals, median_of(s.residuals, s), s.kept);
  const std::optional<PlaneFit> core = fit_plane(points, s.kept);
  if (!core) return 0;
  residuals_of(core->normal, core->offset, plane, points, o, s.residuals);
  const double gate = std::max(o.refit_gate * kMadToSigma * median_of(s.residuals, s),
                               1e-6 * o.inlier_distance);
  keep_within(plane, s.residuals, gate, s.kept);
  const int removed = static_cast<int>(plane.points.size() - s.kept.size());
  if (removed == 0) return 0;
  EmPlane next = plane;
  next.points.swap(s.kept);
  if (!refit(next, points)) return 0;
  plane = std::move(next);
  return removed;
}

}  // namespace

int tight_refit(std::vector<EmPlane>& planes, std::span<const Eigen::Vector3d> points, const EmOptions& o) {
  if (!(o.refit_gate > 0.0)) return 0;
  int removed = 0;
  Scratch scratch;
  for (EmPlane& plane : planes) {
    if (plane.points.size() < 3) continue;
    for (int round = 0; round < o.refit_rounds; ++round) {
      const int gone = gate_once(plane, points, o, scratch);
      if (gone == 0) break;
      removed += gone;
    }
  }
  return removed;
}

}  // namespace relslam::em
