#pragma once
// What relslam victoria-park reads of the Victoria Park data set (thesis 6.8): which scans and
// which tree detections reach the algorithms. describe() gives each field's key, help and
// checks (relslam/core/option_fields.hpp).

#include "relslam/core/option_fields.hpp"

#include <limits>
#include <string>
#include <vector>

namespace relslam::eval {

// Detections kept for the algorithms [C: every one by default].
struct DetectionFilter {
  double min_range = 0;     // m
  double max_range = 1000;  // m: past every detection (the farthest is 75.3 m)
  double min_diameter = 0;  // m
  bool keeps(double range, double diameter) const {
    return range >= min_range && range <= max_range && diameter >= min_diameter;
  }
};

// The keys of the filter (victoria_park.min_range, ...).
void describe(OptionsOf<DetectionFilter> auto& f, auto& fields) {
  fields.field("min_range", f.min_range, "trees nearer than this are dropped, m", at_least(0.0));
  fields.field("max_range", f.max_range, "trees farther than this are dropped, m", above(f.min_range));
  fields.field("min_diameter", f.min_diameter, "trees thinner than this are dropped, m", at_least(0.0));
}

// An inclusive range of 1-based scan indices, "1181:1642", or "all".
struct ScanWindow {
  int first = 1;
  int last = std::numeric_limits<int>::max();
};
// Throws InputError(field `field`) when the text is neither form or first > last.
ScanWindow parse_scan_window(const std::string& text, const std::string& field);
// The check of a window's text: parse_scan_window's problem, if it has one.
struct ScanWindowText {
  void operator()(std::vector<OptionIssue>& issues, const std::string& field, const std::string& text) const;
};

// What relslam victoria-park reads of the data set.
struct VictoriaParkOptions {
  std::string window = "1181:1642";  // 1-based scans FIRST:LAST, or all (the thesis's first window)
  DetectionFilter filter;            // detections kept
};

// The scenario keys of VictoriaParkOptions (victoria_park.*); the filter's sit beside window.
void describe(OptionsOf<VictoriaParkOptions> auto& o, auto& f) {
  f.field("window", o.window, "scans FIRST:LAST (1-based, of 7249) or all; relslam victoria-park --window overrides",
          ScanWindowText{});
  f.nested("", o.filter);
}

}  // namespace relslam::eval
