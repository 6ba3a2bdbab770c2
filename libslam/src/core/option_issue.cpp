#include "relslam/core/option_issue.hpp"

#include <cmath>
#include <charconv>

namespace relslam {
std::string format_number(double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

OptionError::OptionError(std::string field, std::string problem)
    : std::invalid_argument(field + ": " + problem), field_(std::move(field)), problem_(std::move(problem)) {}

// NaN fails every comparison, so each helper rejects it explicitly with the same wording.
void require_at_least(std::vector<OptionIssue>& issues, const std::string& field, double value, double minimum) {
  if (!(value >= minimum) || !std::isfinite(value))
    issues.push_back({field, "must be >= " + format_number(minimum) + ", got " + format_number(value)});
}

void require_above(std::vector<OptionIssue>& issues, const std::string& field, double value, double bound) {
  if (!(value > bound) || !std::isfinite(value))
    issues.push_back({field, "must be > " + format_number(bound) + ", got " + format_number(value)});
}

void require_at_most(std::vector<OptionIssue>& issues, const std::string& field, double value, double maximum) {
  if (!(value <= maximum) || !std::isfinite(value))
    issues.push_back({field, "must be <= " + format_number(maximum) + ", got " + format_number(value)});
}

}  // namespace relslam
