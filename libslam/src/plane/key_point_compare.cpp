#include "relslam/plane/key_point_compare.hpp"

#include "relslam/plane/growth_phase.hpp"
#include "relslam/plane/key_points.hpp"

#include <algorithm>
#include <vector>

namespace relslam::plane {

CompareResult compare_with_key_points(std::span<const PlaneObject> first, std::span<const PlaneObject> second,
                                      const RelativePlaneOptions& options, std::optional<int> forced_iteration) {
  // GetCombinedInterval: the iterations both planes were seen in, by a merge walk.
  std::vector<PlaneObject> both1, both2;
  std::vector<SizeSample> sizes;
  for (std::size_t i = 0, j = 0; i < first.size() && j < second.size();) {
    if (first[i].iteration != second[j].iteration) {
      (first[i].iteration < second[j].iteration ? i : j) += 1;
      continue;
    }
    both1.push_back(first[i]);
    both2.push_back(second[j]);
    sizes.push_back({first[i].iteration, first[i].length(), second[j].length()});
    ++i, ++j;
  }
  CompareResult result;
  const std::optional<SizeInterval> piece =
      get_max_size(sizes, options.growth_phase, options.interval_choice, forced_iteration);
  if (!piece) return result;  // size 0: the reference is invalid [T]
  const std::span<const PlaneObject> in1 = std::span(both1).subspan(piece->first, piece->samples);
  const std::span<const PlaneObject> in2 = std::span(both2).subspan(piece->first, piece->samples);
  const KeyPointPairs pairs = key_point_pairs(in1, in2, options.rules.rotate_to_first);
  const KeyPointChoice choice = choose_key_points(pairs, options.key_point_ties);
  result.valid = true;
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
  result.interval = piece->interval;
  result.samples = piece->samples;
  for (std::size_t k = 0; k < in1.size(); ++k) {  // static in the simulator: the maximum [R, A44]
    result.height1 = std::max(result.height1, in1[k].height());
    result.height2 = std::max(result.height2, in2[k].height());
  }
  return result;
}

}  // namespace relslam::plane
