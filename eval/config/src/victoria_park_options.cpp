#include "relslam/eval/config/victoria_park_options.hpp"

#include "relslam/eval/config/input_error.hpp"

#include <cstdlib>

namespace relslam::eval {

std::vector<OptionIssue> check(const DetectionFilter& f) {
  std::vector<OptionIssue> issues;
  require_at_least(issues, "min_range", f.min_range, 0.0);
  require_above(issues, "max_range", f.max_range, f.min_range);
  require_at_least(issues, "min_diameter", f.min_diameter, 0.0);
  return issues;
}

ScanWindow parse_scan_window(const std::string& text, const std::string& field) {
  if (text == "all") return {};
  const std::size_t colon = text.find(':');
  auto number = [&](const std::string& part) {
    char* end = nullptr;
    const long v = std::strtol(part.c_str(), &end, 10);
    if (part.empty() || *end != '\0' || v < 1 || v > 1000000)
      throw InputError("", 0, field, "expected FIRST:LAST (1-based scan indices) or all, got \"" + text + "\"");
    return static_cast<int>(v);
  };
  if (colon == std::string::npos) number("");
  const ScanWindow w{number(text.substr(0, colon)), number(text.substr(colon + 1))};
  if (w.first > w.last) throw InputError("", 0, field, "the window's first scan comes after its last: \"" + text + "\"");
  return w;
}

}  // namespace relslam::eval
