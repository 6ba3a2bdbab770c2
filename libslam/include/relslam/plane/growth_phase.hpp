#pragma once
// GetMaxSize (thesis 4.3.4 Rule 18, walkthrough 4.5 "RltPlaneCompare GetMaxSize"): the iterations two planes are compared over are split wherever
// either plane switches between growing and shrinking. A wall passed in a hallway first grows
// from its far end and then shrinks towards it from the near side, so different key points are
// valid before and after the switch; the four σ of Rules 13–15 are only meaningful inside one
// growth phase. Part of relslam/plane.

#include "relslam/plane/rlt_interval.hpp"

#include <optional>
#include <span>
#include <vector>

namespace relslam::plane {

// The constants of the split (the thesis names only "a moving average" and "some
// hysteresis" [T]).
struct GrowthPhaseBounds {
  // w_ma: trailing moving average of the lengths, "for noise reasons" [T]; 5 [R]. Larger hides
  // noise but misses the switch of a plane seen only briefly (Fig 105) [T].
  int window = 5;
  // h: the average must move this far back from its extreme before the phase counts as
  // switched, units [R 0.03; thesis 4.3.4 suggests max(0.03, 3σ_len)].
  double hysteresis = 0.03;
  // n_min_cmp: sub-intervals with fewer iterations are dropped [R 3].
  int min_samples = 3;
};

// Which sub-interval a comparison uses.
enum class IntervalChoice : unsigned char {
  MostIterations,  // Rule 18 [T]; ties: the larger L1 + L2
  LargestSize,     // the walkthrough's "greatest total size of both planes" [T]; ties: more iterations
};

// The indices (into `lengths`, one plane's lengths at consecutive iterations) at which a growth
// phase ends: the iteration of the extreme the phase reached. A sub-interval ends there and the
// next begins one later. The state machine of thesis 4.3.4 on the trailing moving average ma:
// NONE becomes GROW or SHRINK once ma leaves its first value by more than `hysteresis`; in a
// phase, the extreme r follows ma, and ma coming back from r by more than `hysteresis` splits
// at r's iteration and starts the opposite phase. A plateau continues the phase, so
// grow → plateau → shrink splits once, inside the plateau. The trailing average lags: a sharp
// peak at k splits at k + (window − 1)/2.
std::vector<int> growth_phase_splits(std::span<const double> lengths, int window, double hysteresis);

// Both planes' lengths at one iteration in which both were observed.
struct SizeSample {
  int iteration = 0;
  double length1 = 0;
  double length2 = 0;
};

// One sub-interval of constant growth phase, with the planes' maximum sizes in it — the lengths
// the assumed midpoints of Rule 13 are built with.
struct SizeInterval {
  RltInterval interval;  // first and last iteration
  int first = 0;         // index of its first sample in the input
  int samples = 0;       // samples in it (= interval.size(): runs have no missing iterations)
  double length1 = 0;
  double length2 = 0;
};

// Every sub-interval of `samples` (sorted by iteration): runs break at every missing iteration
// (thesis 4.3.3, gap_max = 1, A39) and each run is split wherever either plane's phase switches.
// Sub-intervals with fewer than bounds.min_samples samples are dropped.
std::vector<SizeInterval> split_by_growth_phase(std::span<const SizeSample> samples, const GrowthPhaseBounds& bounds);

// GetMaxSize: the sub-interval to compare over — by `choice`, or, when `forced_iteration` is
// given, the one containing that iteration (Rule 19: a key point recomputed inside a given
// interval). nullopt when there is none: the comparison is invalid [T].
std::optional<SizeInterval> get_max_size(std::span<const SizeSample> samples, const GrowthPhaseBounds& bounds,
                                         IntervalChoice choice, std::optional<int> forced_iteration = {});

// GetMaxSize's order: `x` is a better piece than `y` by `choice`. get_max_size keeps the first
// of equal pieces in iteration order.
bool better_piece(const SizeInterval& x, const SizeInterval& y, IntervalChoice choice);

}  // namespace relslam::plane
