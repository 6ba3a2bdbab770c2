#include "relslam/plane/growth_phase.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace relslam::plane {
namespace {

enum class Phase : unsigned char { None, Grow, Shrink };

// Splits of both planes over samples[begin, end), one run of consecutive iterations, as indices
// into `samples`.
void split_run(std::span<const SizeSample> samples, int begin, int end, const GrowthPhaseBounds& bounds,
               std::vector<int>& splits) {
  std::vector<double> l1, l2;
  for (int k = begin; k < end; ++k) {
    l1.push_back(samples[k].length1);
    l2.push_back(samples[k].length2);
  }
  for (const std::vector<double>* lengths : {&l1, &l2})
    for (int k : growth_phase_splits(*lengths, bounds.window, bounds.hysteresis)) splits.push_back(begin + k);
}

}  // namespace

std::vector<int> growth_phase_splits(std::span<const double> lengths, int window, double hysteresis) {
  if (window < 1) throw std::invalid_argument("growth_phase_splits: window must be >= 1");
  std::vector<int> splits;
  Phase phase = Phase::None;
  double sum = 0, extreme = 0;
  int extreme_at = 0;
  for (int k = 0; k < static_cast<int>(lengths.size()); ++k) {
    // Trailing moving average over the last `window` samples (fewer at the start of the run).
    sum += lengths[k];
    if (k >= window) sum -= lengths[k - window];
    const double ma = sum / std::min(k + 1, window);
    if (k == 0) {
      extreme = ma;
      continue;
    }
    switch (phase) {
      case Phase::None:
        if (std::abs(ma - extreme) > hysteresis) {
          phase = ma > extreme ? Phase::Grow : Phase::Shrink;
          extreme = ma;
          extreme_at = k;
        }
        break;
      case Phase::Grow:
      case Phase::Shrink: {
        const bool further = phase == Phase::Grow ? ma > extreme : ma < extreme;
        if (further) {
          extreme = ma;
          extreme_at = k;
        } else if (std::abs(ma - extreme) > hysteresis) {
          // The switch happened at the extreme; what follows belongs to the opposite phase.
          splits.push_back(extreme_at);
          phase = phase == Phase::Grow ? Phase::Shrink : Phase::Grow;
          extreme = ma;
          extreme_at = k;
        }
        break;
      }
    }
  }
  return splits;
}

std::vector<SizeInterval> split_by_growth_phase(std::span<const SizeSample> samples, const GrowthPhaseBounds& bounds) {
  const int n = static_cast<int>(samples.size());
  // Sub-interval ends: the last sample of each run and every split inside one.
  std::vector<int> ends;
  for (int begin = 0; begin < n;) {
    int end = begin + 1;
    while (end < n && samples[end].iteration == samples[end - 1].iteration + 1) ++end;
    split_run(samples, begin, end, bounds, ends);
    ends.push_back(end - 1);
    begin = end;
  }
  std::ranges::sort(ends);
  // std::unique, not std::ranges::unique: clang 14 (the fuzz build) cannot compile the
  // subrange libstdc++ 12's ranges::unique returns.
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());

  std::vector<SizeInterval> intervals;
  int first = 0;
  for (int last : ends) {
    SizeInterval s;
    s.first = first;
    s.samples = last - first + 1;
    s.interval = {samples[first].iteration, samples[last].iteration};
    for (int k = first; k <= last; ++k) {
      s.length1 = std::max(s.length1, samples[k].length1);
      s.length2 = std::max(s.length2, samples[k].length2);
    }
    if (s.samples >= bounds.min_samples) intervals.push_back(s);
    first = last + 1;
  }
  return intervals;
}

std::optional<SizeInterval> get_max_size(std::span<const SizeSample> samples, const GrowthPhaseBounds& bounds,
                                         IntervalChoice choice, std::optional<int> forced_iteration) {
  const std::vector<SizeInterval> intervals = split_by_growth_phase(samples, bounds);
  if (forced_iteration) {
    for (const SizeInterval& s : intervals)
      if (s.interval.in_interval(*forced_iteration)) return s;
    return std::nullopt;
  }
  std::optional<SizeInterval> best;
  for (const SizeInterval& s : intervals)
    if (!best || better_piece(s, *best, choice)) best = s;
  return best;
}

bool better_piece(const SizeInterval& x, const SizeInterval& y, IntervalChoice choice) {
  const double size_x = x.length1 + x.length2, size_y = y.length1 + y.length2;
  if (choice == IntervalChoice::MostIterations) return x.samples != y.samples ? x.samples > y.samples : size_x > size_y;
  return size_x != size_y ? size_x > size_y : x.samples > y.samples;
}

}  // namespace relslam::plane
