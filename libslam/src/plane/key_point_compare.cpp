#include "relslam/plane/key_point_compare.hpp"

#include "relslam/plane/growth_phase.hpp"
#include "relslam/plane/key_points.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace relslam::plane {
namespace {

// Component-wise median of 2-D offsets (sorts a copy).
Eigen::Vector2d median_of(std::vector<Eigen::Vector2d> v) {
  Eigen::Vector2d m;
  for (int c = 0; c < 2; ++c) {
    std::ranges::nth_element(v, v.begin() + v.size() / 2, {}, [c](const Eigen::Vector2d& x) { return x[c]; });
    m[c] = v[v.size() / 2][c];
  }
  return m;
}

// Rule 18's split points are known only to within the moving average (thesis 4.3.4: ± w_ma), and a
// plane first seen cut at both ends (the frustum's far corner, Fig 105) or whose real end leaves
// the view at the piece's end opens or closes the piece with samples in which its real end was
// not in view: the series of the pair of real ends then jumps there and is constant elsewhere,
// and a pair of slowly drifting cut ends can beat it on σ (thesis Figs 76–79, 105: wrong key
// points from observations left in the wrong sub-interval). [C] Each pair's series is judged on
// its consistent part: samples at the two ends of the piece standing off the series — beyond
// four robust σ (1.4826·MAD about the median) and the noise-free tie ε_σ — are left out while at
// least `min_samples` stay. A drifting series has no such outliers (its ends sit within 2 MAD).
struct ConsistentRange {
  std::size_t first = 0, last = 0;  // [first, last)
  double sigma = 0;                 // the pair's σ over it
};

// `offsets`: key_point_pairs' series over the piece; `pair` = 2(a − 1) + (b − 1).
ConsistentRange consistent_range(const std::vector<KeyPointOffsets>& offsets, int pair,
                                 const ComparePlanesOptions& options) {
  const std::size_t n = offsets.size();
  std::vector<Eigen::Vector2d> series(n);
  for (std::size_t t = 0; t < n; ++t) series[t] = offsets[t][pair];
  const Eigen::Vector2d median = median_of(series);
  std::vector<double> deviation(n);
  for (std::size_t t = 0; t < n; ++t) deviation[t] = (series[t] - median).norm();
  std::vector<double> sorted = deviation;
  std::ranges::nth_element(sorted, sorted.begin() + n / 2);
  const double limit = std::max(options.key_point_ties.absolute, 4 * 1.4826 * sorted[n / 2]);
  ConsistentRange range{0, n, 0};
  const std::size_t keep = static_cast<std::size_t>(std::max(1, options.growth_phase.min_samples));
  while (range.last - range.first > keep && deviation[range.first] > limit) ++range.first;
  while (range.last - range.first > keep && deviation[range.last - 1] > limit) --range.last;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (std::size_t t = range.first; t < range.last; ++t) mean += series[t];
  mean /= static_cast<double>(range.last - range.first);
  double squares = 0;
  for (std::size_t t = range.first; t < range.last; ++t) squares += (series[t] - mean).squaredNorm();
  range.sigma = std::sqrt(squares / static_cast<double>(range.last - range.first));
  return range;
}

}  // namespace

void common_sizes(const ObservationView& first, const ObservationView& second, int from_iteration, int to_iteration,
                  std::vector<SizeSample>& out) {
  for (int i = first.lower_bound(from_iteration), j = second.lower_bound(from_iteration);
       i < first.size() && j < second.size();) {
    const int a = first[i].iteration, b = second[j].iteration;
    if (std::min(a, b) > to_iteration) break;
    if (a != b) {
      (a < b ? i : j) += 1;
      continue;
    }
    out.push_back({a, first[i].length(), second[j].length()});
    ++i, ++j;
  }
}

CompareResult compare_with_key_points(const ObservationView& first, const ObservationView& second,
                                      const ComparePlanesOptions& options, std::optional<int> forced_iteration) {
  std::vector<SizeSample> sizes;
  if (!forced_iteration) {
    common_sizes(first, second, std::numeric_limits<int>::min(), std::numeric_limits<int>::max(), sizes);
  } else {
    // Rule 18 splits each run of consecutive common iterations on its own, so the piece holding
    // the iteration lies in the run around it: only that run is read.
    const int f = *forced_iteration;
    const int i = first.lower_bound(f), j = second.lower_bound(f);
    if (i == first.size() || j == second.size() || first[i].iteration != f || second[j].iteration != f)
      return {};  // not seen together then: no piece holds it [T]
    int back = 0, ahead = 0;
    while (i - back > 0 && j - back > 0 && first[i - back - 1].iteration == f - back - 1 &&
           second[j - back - 1].iteration == f - back - 1)
      ++back;
    while (i + ahead + 1 < first.size() && j + ahead + 1 < second.size() &&
           first[i + ahead + 1].iteration == f + ahead + 1 && second[j + ahead + 1].iteration == f + ahead + 1)
      ++ahead;
    common_sizes(first, second, f - back, f + ahead, sizes);
  }
  const std::optional<SizeInterval> piece =
      get_max_size(sizes, options.growth_phase, options.interval_choice, forced_iteration);
  if (!piece) return {};  // size 0: the reference is invalid [T]
  return compare_piece(first, second, *piece, options);
}

CompareResult compare_piece(const ObservationView& first, const ObservationView& second, const SizeInterval& piece,
                            const ComparePlanesOptions& options) {
  // The piece's observations: consecutive in both histories, as both planes were seen in each
  // of its iterations.
  std::vector<PlaneObject> both1, both2;
  both1.reserve(piece.samples);
  both2.reserve(piece.samples);
  first.copy(first.lower_bound(piece.interval.start), piece.samples, both1);
  second.copy(second.lower_bound(piece.interval.start), piece.samples, both2);
  CompareResult result;
  std::span<const PlaneObject> in1(both1), in2(both2);
  std::vector<KeyPointOffsets> offsets;
  KeyPointPairs pairs = key_point_pairs(in1, in2, options.rotate_to_first, &offsets);
  if (options.cut_ends_open) {
    // open_cut_ends: the sensor says which ends are cut, so the samples a cut end spoils
    // are known and left out pair by pair (restrict_to_real_ends) instead of trimmed.
    restrict_to_real_ends(in1, in2, offsets, options.growth_phase.min_samples, pairs);
    if (std::min({pairs.sigma[0][0], pairs.sigma[0][1], pairs.sigma[1][0], pairs.sigma[1][1]}) >= kCutEndSigma)
      return result;  // no pair of real ends in view together: nothing places the one from the other
  }
  KeyPointChoice choice = choose_key_points(pairs, options.key_point_ties, options.rotate_to_first);
  RltInterval interval = piece.interval;
  if (options.trim_piece_ends && !options.cut_ends_open && in1.size() > static_cast<std::size_t>(options.growth_phase.min_samples)) {
    // The pair with the lowest σ over its consistent part; when that part is not the whole
    // piece, and its σ is clearly below the whole piece's lowest, the comparison is made again
    // over it.
    ConsistentRange best;
    bool any = false;
    for (int pair = 0; pair < 4; ++pair) {  // (1,1), (1,2), (2,1), (2,2)
      const ConsistentRange r = consistent_range(offsets, pair, options);
      if (!any || r.sigma < best.sigma) best = r;
      any = true;
    }
    // Only a clearly better pair counts: a tie with the whole piece's lowest σ keeps the piece.
    const double lowest = pairs.sigma_of(choice.anchor1, choice.anchor2);
    if (best.last - best.first < in1.size() && !options.key_point_ties.close(best.sigma, lowest)) {
      in1 = in1.subspan(best.first, best.last - best.first);
      in2 = in2.subspan(best.first, best.last - best.first);
      pairs = key_point_pairs(in1, in2, options.rotate_to_first);
      choice = choose_key_points(pairs, options.key_point_ties, options.rotate_to_first);
      interval = {in1.front().iteration, in1.back().iteration};
    }
  }
  // Rule 13 refined [C]: no pair of ends kept its offset, so no key point is real (rigid_sigma).
  const double sigma = pairs.sigma_of(choice.anchor1, choice.anchor2);
  if (options.rigid_sigma > 0 && sigma > options.rigid_sigma) return result;
  result.valid = true;
  result.sigma = sigma;
  result.delta = choice.delta;
  result.length1 = pairs.length1;
  result.length2 = pairs.length2;
  result.key_point1 = choice.key_point1;
  result.key_point2 = choice.key_point2;
  result.static1 = choice.static1;
  result.static2 = choice.static2;
  result.ambiguous = choice.ambiguous;
  for (KeyPoint a : {KeyPoint::Left, KeyPoint::Right})
    for (KeyPoint b : {KeyPoint::Left, KeyPoint::Right})
      result.pair_delta[a == KeyPoint::Right][b == KeyPoint::Right] = pairs.delta(a, b);
  result.interval = interval;
  result.samples = static_cast<int>(in1.size());
  for (std::size_t k = 0; k < in1.size(); ++k) {  // static in the simulator: the maximum [R, A44]
    result.height1 = std::max(result.height1, in1[k].height());
    result.height2 = std::max(result.height2, in2[k].height());
  }
  return result;
}

}  // namespace relslam::plane
