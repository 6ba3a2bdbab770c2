#pragma once
// The segmentation comparison of Hoover et al. 1996 ("An experimental comparison of range
// image segmentation algorithms", SegComp): a machine segmentation's regions against the
// ground truth's, each pair by the points they share, at an overlap tolerance T (0.5 < T <= 1).
// Five classes: a correct detection (one to one), an over-segmentation (one true region, many
// machine regions), an under-segmentation (one machine region, many true ones), a missed true
// region and a noise machine region.

#include <span>
#include <utility>
#include <vector>

namespace relslam::eval {

struct SegCompCounts {
  int correct = 0;
  int over_segmented = 0;   // true regions split into several machine regions
  int under_segmented = 0;  // machine regions covering several true regions
  int missed = 0;           // true regions in no class
  int noise = 0;            // machine regions in no class
  std::vector<std::pair<int, int>> correct_pairs;  // (true region, machine region), ascending
};

// truth[i]: the true region of point i, 0 .. truth_regions - 1, or -1 for a point of no counted
// region. machine[m]: the points of machine region m (indices into truth; a point may be in
// several). Correct: overlap O >= T·|M| and O >= T·|G|. Over-segmented: G with machine regions
// M_1..M_x (x >= 2, not correct) each O_i >= T·|M_i| and sum O_i >= T·|G|. Under-segmented: M
// with true regions G_1..G_x (x >= 2, unclassified) each O_i >= T·|G_i| and sum O_i >= T·|M|.
SegCompCounts segcomp(std::span<const int> truth, int truth_regions, const std::vector<std::vector<int>>& machine,
                      double tolerance);

}  // namespace relslam::eval
