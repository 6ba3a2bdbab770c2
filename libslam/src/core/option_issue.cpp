#include "relslam/core/option_issue.hpp"

#include <cmath>
#include <sstream>

namespace relslam {
namespace {

std::string number(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

}  // namespace

OptionError::OptionError(std::string field, std::string problem)
    : std::invalid_argument(field + ": " + problem), field_(std::move(field)), problem_(std::move(problem)) {}

// NaN fails every comparison, so each helper rejects it explicitly with the same wording.
void require_at_least(std::vector<OptionIssue>& issues, const std::string& field, double value, double minimum) {
  if (!(value >= minimum) || !std::isfinite(value))
    issues.push_back({field, "must be >= " + number(minimum) + ", got " + number(value)});
}

void require_above(std::vector<OptionIssue>& issues, const std::string& field, double value, double bound) {
  if (!(value > bound) || !std::isfinite(value))
    issues.push_back({field, "must be > " + number(bound) + ", got " + number(value)});
}

void require_at_most(std::vector<OptionIssue>& issues, const std::string& field, double value, double maximum) {
  if (!(value <= maximum) || !std::isfinite(value))
    issues.push_back({field, "must be <= " + number(maximum) + ", got " + number(value)});
}

}  // namespace relslam
