#pragma once
// ComparePlanes for growing and shrinking planes (thesis 4.3.4, walkthrough 4.5 "RltPlaneCompare
// ComparePlanes"; thesis 4.3.4): over the iterations both planes were seen,
// GetMaxSize picks one growth phase (Rule 18), and inside it the four assumed-midpoint pairs
// give the offset and the key points (Rules 13–15). A pure function of two observation series,
// so CalculateMissingKeyPoints (Rule 19) and the tests need no RltPlane; the group computation
// calls it on an RltPlane's stored observations (RltPlane::view, PairComparison). Part of relslam/plane.

#include "relslam/core/plane_object.hpp"
#include "relslam/plane/compare_result.hpp"
#include "relslam/plane/growth_phase.hpp"
#include "relslam/plane/observation_view.hpp"
#include "relslam/plane/options.hpp"

#include <optional>
#include <vector>

namespace relslam::plane {

// What ComparePlanes reads of RelativePlaneOptions (Rules 13–15, 18, 19). Converts from the whole
// options, so a caller holding them passes them as they are; the view copies the few values.
struct ComparePlanesOptions {
  GrowthPhaseBounds growth_phase;  // Rule 18's pieces
  IntervalChoice interval_choice;  // which piece GetMaxSize picks
  KeyPointTies key_point_ties;     // Rule 15's ties
  bool rotate_to_first;            // rules.rotate_to_first
  bool trim_piece_ends;            // the piece's ends standing off the series left out
  double rigid_sigma;              // Rule 13 refined: no key point above this σ
  bool cut_ends_open;              // open_cut_ends: an end the sensor cut is no key point
  ComparePlanesOptions() : ComparePlanesOptions(RelativePlaneOptions{}) {}  // the defaults of RelativePlaneOptions
  ComparePlanesOptions(const RelativePlaneOptions& o)                       // NOLINT(google-explicit-constructor)
      : growth_phase(o.growth_phase),
        interval_choice(o.interval_choice),
        key_point_ties(o.key_point_ties),
        rotate_to_first(o.rules.rotate_to_first),
        trim_piece_ends(o.trim_piece_ends),
        rigid_sigma(o.rigid_sigma),
        cut_ends_open(plane::cut_ends_open(o)) {}
};

// `first` and `second`: each plane's observations, sorted by iteration (one per iteration).
// The result's delta is the pair with the lowest σ, at the planes' maximum lengths in the chosen
// piece; interval and samples are that piece's. With `forced_iteration` the piece containing it
// is used (Rule 19), and only the run of common iterations around it is read. Invalid when no
// piece has options.growth_phase.min_samples iterations [T].
CompareResult compare_with_key_points(const ObservationView& first, const ObservationView& second,
                                      const ComparePlanesOptions& options,
                                      std::optional<int> forced_iteration = std::nullopt);

// GetCombinedInterval between two iterations (inclusive): both lengths at each iteration both
// planes were seen in, appended to `out` in iteration order (a merge walk started by binary
// search). What Rule 18 splits into growth phases.
void common_sizes(const ObservationView& first, const ObservationView& second, int from_iteration, int to_iteration,
                  std::vector<SizeSample>& out);

// ComparePlanes inside one piece GetMaxSize chose (Rules 13–15, with the piece's ends trimmed,
// options.trim_piece_ends): both planes were seen at every iteration of piece.interval.
CompareResult compare_piece(const ObservationView& first, const ObservationView& second, const SizeInterval& piece,
                            const ComparePlanesOptions& options);

}  // namespace relslam::plane
