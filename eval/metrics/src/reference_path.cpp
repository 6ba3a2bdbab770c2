#include "relslam/eval/metrics/reference_path.hpp"

#include "relslam/eval/metrics/planar_alignment.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace relslam::eval {

ReferencePathError ate_vs_reference(const std::vector<std::optional<PlanarPose>>& estimate,
                                    const std::vector<std::optional<PlanarPose>>& reference) {
  std::vector<Eigen::Vector2d> from, to;
  for (std::size_t i = 0; i < std::min(estimate.size(), reference.size()); ++i)
    if (estimate[i] && reference[i]) {
      from.push_back(estimate[i]->translation);
      to.push_back(reference[i]->translation);
    }
  ReferencePathError out;
  out.pairs = static_cast<int>(from.size());
  if (from.empty()) return out;
  const PlanarAlignment alignment = align_planar(from, to, false);
  double sum2 = 0;
  for (std::size_t i = 0; i < from.size(); ++i) {
    const double e = (alignment.apply(from[i]) - to[i]).norm();
    sum2 += e * e;
    out.max = std::max(out.max, e);
  }
  out.ate = std::sqrt(sum2 / static_cast<double>(from.size()));
  out.rotation_deg = alignment.rotation_deg();
  return out;
}

namespace {

std::optional<PlanarPose> motion(const std::vector<std::optional<PlanarPose>>& path, int first, int second) {
  const auto in = [&](int k) { return k >= 0 && static_cast<std::size_t>(k) < path.size() && path[k]; };
  if (!in(first) || !in(second)) return std::nullopt;
  return path[first]->inverse() * *path[second];
}

}  // namespace

std::optional<LoopGap> loop_gap(const std::vector<std::optional<PlanarPose>>& path, int first, int second,
                                const std::vector<std::optional<PlanarPose>>* reference) {
  std::optional<PlanarPose> claimed = motion(path, first, second);
  if (!claimed) return std::nullopt;
  if (reference) {
    const std::optional<PlanarPose> expected = motion(*reference, first, second);
    if (!expected) return std::nullopt;
    claimed = expected->inverse() * *claimed;
  }
  return LoopGap{claimed->translation.norm(), std::abs(claimed->heading) * 180.0 / std::numbers::pi};
}

}  // namespace relslam::eval
