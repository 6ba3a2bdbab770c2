#include "relslam/eval/config/victoria_park_options.hpp"

#include "relslam/eval/config/input_error.hpp"

#include <cstdlib>

namespace relslam::eval {

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
  if (w.first > w.last)
    throw InputError("", 0, field, "the window's first scan comes after its last: \"" + text + "\"");
  return w;
}

void ScanWindowText::operator()(std::vector<OptionIssue>& issues, const std::string& field,
                                const std::string& text) const {
  try {
    parse_scan_window(text, field);
  } catch (const InputError& e) {
    issues.push_back({field, e.problem()});
  }
}

}  // namespace relslam::eval
