#pragma once
// What relslam victoria-park reads of the Victoria Park data set (thesis 6.8): which scans and
// which tree detections reach the algorithms.

#include "relslam/core/option_issue.hpp"

#include <limits>
#include <string>
#include <vector>

namespace relslam::eval {

// Detections kept for the algorithms [C: every one by default].
struct DetectionFilter {
  double min_range = 0;  // m
  double max_range = 1000;  // m: past every detection (the farthest is 75.3 m)
  double min_diameter = 0;  // m
  bool keeps(double range, double diameter) const {
    return range >= min_range && range <= max_range && diameter >= min_diameter;
  }
};

std::vector<OptionIssue> check(const DetectionFilter& filter);

// An inclusive range of 1-based scan indices, "1181:1642", or "all".
struct ScanWindow {
  int first = 1;
  int last = std::numeric_limits<int>::max();
};
// Throws InputError(field `field`) when the text is neither form or first > last.
ScanWindow parse_scan_window(const std::string& text, const std::string& field);

// What relslam victoria-park reads of the data set.
struct VictoriaParkOptions {
  std::string window = "1181:1642";  // 1-based scans FIRST:LAST, or all (the thesis's first window)
  DetectionFilter filter;            // detections kept
};

}  // namespace relslam::eval
