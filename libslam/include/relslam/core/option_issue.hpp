#pragma once
// How option checks report problems without knowing where the options came from.
// The evaluation layer adds the file, line and key prefix.

#include <stdexcept>
#include <string>
#include <vector>

namespace relslam {

// One violated constraint. `field` is the option's path inside its struct, e.g.
// "dynamic.count"; `problem` reads after it: "must be >= 0, got -1".
struct OptionIssue {
  std::string field;
  std::string problem;
};

// Thrown when options pass their checks but still cannot be honoured once the data exist
// (e.g. more dynamic points requested than are visible at iteration 0).
class OptionError : public std::invalid_argument {
 public:
  OptionError(std::string field, std::string problem);
  const std::string& field() const { return field_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string field_;
  std::string problem_;
};

// Shortest text that reads back to the same double ("0.1", "-5", "1e+20").
std::string format_number(double value);

// The common constraints (at_least, above, at_most, ...) are checks of option_fields.hpp,
// phrased the same way everywhere.

}  // namespace relslam
