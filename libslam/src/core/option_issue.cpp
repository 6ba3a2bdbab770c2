#include "relslam/core/option_issue.hpp"

#include <charconv>

namespace relslam {
std::string format_number(double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

OptionError::OptionError(std::string field, std::string problem)
    : std::invalid_argument(field + ": " + problem), field_(std::move(field)), problem_(std::move(problem)) {}

}  // namespace relslam
