#pragma once
// ComparePlanes with key points (key_point_compare.hpp) for one chain edge of a group, kept up
// to date as the two planes are seen (thesis 4.2.2, 4.3.8: the time per iteration follows the
// planes in view, not the age of the map; E32). It gives exactly
// compare_with_key_points(first.view(), second.view()) without reading the pair's whole history
// every iteration:
//  - the iterations both planes were seen in fall into runs of consecutive iterations, and
//    Rule 18 splits each run on its own; only the last run can still grow, so every earlier
//    ("closed") run is split into growth phases once, and kept until the circular arrays
//    overwrite it;
//  - GetMaxSize picks among the closed runs' pieces and the last run's, in iteration order as
//    get_max_size does;
//  - stored observations never change, so a piece chosen before keeps its comparison.
// Part of relslam/plane: Eigen only.

#include "relslam/plane/compare_result.hpp"
#include "relslam/plane/growth_phase.hpp"
#include "relslam/plane/ids.hpp"
#include "relslam/plane/key_point_compare.hpp"
#include "relslam/plane/options.hpp"
#include "relslam/plane/rlt_plane.hpp"

#include <climits>
#include <optional>
#include <vector>

namespace relslam::plane {

// Invariant: `closed_` holds the growth-phase pieces of every run of common iterations that ended
// before `scanned_until_`, from the newest oldest-stored iteration of the two planes on, and
// `result_` is the comparison over `chosen_`. The options must be the same at every call.
class PairComparison {
 public:
  // The comparison of `first` with `second` (the edge's planes in chain order); nullptr when
  // nothing changed since the last call — the same planes, the same oldest stored observations,
  // no new iteration seen together — so the edge keeps its result.
  const CompareResult* update(const RltPlane& first, const RltPlane& second, const ComparePlanesOptions& options);

 private:
  // A run of consecutive common iterations and its growth phases (Rule 18).
  struct Run {
    int first = 0, last = 0;
    std::vector<SizeInterval> pieces;
  };
  struct Source {
    PlaneId first = -1, second = -1;
    int oldest_first = 0, oldest_second = 0;
    int last_common = 0;
    bool operator==(const Source&) const = default;
  };
  Source source_;
  std::vector<Run> closed_;
  int scanned_until_ = INT_MIN;  // every run ending before this is in closed_
  std::optional<SizeInterval> chosen_;
  CompareResult result_;

  void reset();
  // Appends the runs of common iterations in [from, to] with their pieces.
  void add_runs(const ObservationView& a, const ObservationView& b, int from, int to, const GrowthPhaseBounds& bounds,
                std::vector<Run>& out) const;
};

}  // namespace relslam::plane
