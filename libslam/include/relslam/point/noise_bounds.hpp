#pragma once
// Matching bounds scaled with the sensor noise (beyond the thesis). The thesis tuned
// its bounds to noise sigma 0.1 (thesis 6.6.1); at sigma 0.2 a quarter of the map came out as
// duplicates, because two observations of one point then differ by more than the bounds allow.

#include "relslam/point/options.hpp"

namespace relslam::point {

// The sensor noise every thesis bound was tuned for, units per axis [T 6.6.1].
inline constexpr double kThesisNoiseSigma = 0.1;

struct NoiseBounds {
  double local_bound;        // first local pass: the frame motion plus two observations' noise
  double compensated_bound;  // second local pass: noise only
  double global_bound;       // re-finding a place: the map's error, which grows with the noise
  double merge_bound;        // same reasoning as global_bound
  // RltBinning's threshold gaps (thesis 6.5.3): with more noise the static pairs' deviations
  // spread wider, and at the thesis's gaps static points were split off as dynamic [C].
  double binning_abs_gap;
  double binning_rel_gap;
};

// Bounds for per-axis noise `sigma` (at the sensor's farthest range, where it is largest):
// the thesis's bounds (options' defaults) at sigma <= 0.1; above it the noise terms grow in
// proportion — compensated and global as sigma/0.1, the local bound by the same increment as
// the compensated one (its motion share stays) [C]. Never below the thesis's values: less noise
// makes no bound unsafe.
NoiseBounds noise_scaled_bounds(double sigma);

// Sets the bounds of `options` that `keep` does not name, and widens the index cells to hold
// them (a cell's overlap must hold a whole bound).
struct KeepBounds {
  bool local = false, compensated = false, global = false, merge = false, abs_gap = false, rel_gap = false;
};
void apply_noise_bounds(const NoiseBounds& bounds, const KeepBounds& keep, PointSlamOptions& options);

}  // namespace relslam::point
