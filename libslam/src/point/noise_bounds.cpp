#include "relslam/point/noise_bounds.hpp"

#include <algorithm>

namespace relslam::point {

NoiseBounds noise_scaled_bounds(double sigma) {
  const PointSlamOptions thesis;
  const double scale = std::max(1.0, sigma / kThesisNoiseSigma);
  const double compensated = thesis.compensated_bound * scale;
  return {.local_bound = thesis.local_bound + (compensated - thesis.compensated_bound),
          .compensated_bound = compensated,
          .global_bound = thesis.global_bound * scale,
          .merge_bound = thesis.merge_bound * scale,
          .binning_abs_gap = thesis.binning.abs_gap * scale,
          .binning_rel_gap = thesis.binning.rel_gap * scale};
}

void apply_noise_bounds(const NoiseBounds& bounds, const KeepBounds& keep, PointSlamOptions& o) {
  if (!keep.local) o.local_bound = bounds.local_bound;
  if (!keep.compensated) o.compensated_bound = std::min(bounds.compensated_bound, o.local_bound);
  if (!keep.global) o.global_bound = bounds.global_bound;
  if (!keep.merge) o.merge_bound = bounds.merge_bound;
  if (!keep.abs_gap) o.binning.abs_gap = bounds.binning_abs_gap;
  if (!keep.rel_gap) o.binning.rel_gap = bounds.binning_rel_gap;
  o.local_cell_size = std::max(o.local_cell_size, o.local_bound);
  o.octree_cell_size = std::max(o.octree_cell_size, o.local_bound);
  o.global_cell_size = std::max({o.global_cell_size, o.global_bound, o.merge_bound});
}

}  // namespace relslam::point
