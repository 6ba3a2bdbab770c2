#pragma once
// RltBinning (thesis 6.5.3): which members of a new group move independently of the
// viewpoint. Two static points keep a constant distance in every untransformed observation,
// so the standard deviation of that distance separates correlated pairs from the rest.

#include "relslam/core/option_fields.hpp"
#include "relslam/point/rlt_point.hpp"

#include <functional>
#include <string_view>
#include <vector>

namespace relslam::point {

// How bins meet in a round.
enum class BinPairing {
  // Each bin in at most one comparison per round (a tournament): every comparison between
  // static bins is a merge, so all-static input costs exactly n - 1 comparisons, the thesis's
  // stated best case. [C]
  Disjoint,
  // Every valid bin initiates one comparison per round with the first bin after it not yet
  // compared (thesis 6.5.3's reading of thesis 6.5.3): redundant comparisons in the first round
  // (n instead of n - 1 for all-static input) and, without the heuristic, the thesis's
  // polynomial growth from 20-30 % uncorrelated points (Fig 113).
  EveryBin,
};
std::string_view to_string(BinPairing pairing);  // "disjoint", "every_bin"

struct BinningOptions {
  BinPairing pairing = BinPairing::Disjoint;
  // The automatic threshold (thesis 6.5.3): the first gap between consecutive sorted
  // first-round standard deviations that exceeds both abs_gap and rel_gap times the lower one
  // [C values; thesis 6.5.3: static pairs have ~sigma·sqrt(2) ≈ 0.14 at sigma 0.1].
  double abs_gap = 0.05;  // units
  double rel_gap = 0.5;
  // Threshold = lower value of the gap plus half the minimum gap (a margin for pairs just above
  // the cluster), or the lower value itself (the thesis's wording) when false [C].
  bool threshold_margin = true;
  // Pairs with fewer common observations count as uncorrelated [C].
  int min_pair_samples = 5;
  // Stop pairing once one bin holds more than this share of the points; the rest are then
  // compared with that bin only [T, Fig 115: 50 %].
  double majority_fraction = 0.5;
  // The priority heuristic (thesis 6.5.3): from the second round on, bins that merged last
  // round initiate the comparisons [T].
  bool priority_heuristic = true;
  // After binning, each point outside the largest bin is compared once more, by itself, with
  // that bin's representative. A bin is compared only through its first point, so a bin whose
  // first point moves takes its static members down with it; this pass gives them back
  // (one comparison per point left out) [C].
  bool recheck_members = true;
};

// The scenario keys of BinningOptions (relative_point.binning.*): help and checks per field.
void describe(OptionsOf<BinningOptions> auto& o, auto& f) {
  f.choice("pairing", o.pairing, "bins meet disjointly per round, or every bin initiates (thesis 6.5.3)",
           {BinPairing::Disjoint, BinPairing::EveryBin});
  f.field("abs_gap", o.abs_gap, "threshold gap, absolute part, units; adaptive: scaled with the noise", at_least(0.0));
  f.field("rel_gap", o.rel_gap, "threshold gap, relative part; adaptive: scaled with the noise", at_least(0.0));
  f.field("threshold_margin", o.threshold_margin, "threshold gets half the minimum gap as a margin");
  f.field("min_pair_samples", o.min_pair_samples, "common observations a pair needs", at_least(2));
  f.field("majority_fraction", o.majority_fraction, "a bin holding more than this share ends the pairing (thesis: 0.5)",
          above(0.0), at_most(1.0));
  f.field("priority_heuristic", o.priority_heuristic, "bins that merged initiate the next round (thesis 6.5.3)");
  f.field("recheck_members", o.recheck_members, "each point outside the largest bin is compared once more with it");
}

struct BinningResult {
  std::vector<bool> is_static;  // per input point: in the largest bin
  int comparisons = 0;          // pair standard deviations computed (the recheck included)
  int highest_bin = 0;          // points in the largest bin
  double threshold = 0;
  int rounds = 0;
};

// Bins n points given pair_std(i, j), the standard deviation of their distance (+inf when it
// cannot be computed). In rounds, bins are compared through their first points; a comparison
// within the threshold merges the two bins. The first round's values set the threshold, and
// its merges are applied afterwards through a union-find (a partner may have been merged
// elsewhere meanwhile, thesis 6.5.3). Uncorrelated points cost up to n^2/2 comparisons (6.5.3).
BinningResult rlt_binning(int n, const std::function<double(int, int)>& pair_std, const BinningOptions& options);

// Standard deviation of |a(t) - b(t)| over the iterations in [start, end] where both were
// observed (two passes: mean, then deviation); +inf below min_samples common iterations.
double pair_distance_std(const ObservationRing& a, const ObservationRing& b, int start, int end, int min_samples);

// The threshold from the first round's standard deviations (non-finite ones ignored).
double binning_threshold(std::vector<double> deviations, const BinningOptions& options);

}  // namespace relslam::point
