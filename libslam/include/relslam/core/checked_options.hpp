#pragma once
// How an algorithm's options are checked, the same in every half: one check() per options
// struct (its field descriptions plus the rules between fields) is the only set of rules. Input
// from a user (a scenario, --set) is checked where it is read, by the scenario loader, which
// reports every issue as file:line: key: problem and exits 2. The algorithm's constructor passes
// its options through checked_options, a guard only: reaching its logic_error is a caller's bug
// (options built in code and never checked), not bad input.

#include "relslam/core/option_issue.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace relslam {

// `options` when check(options) finds nothing, else logic_error naming `algorithm` and the first
// issue. check is found beside Options (point::check, plane::check).
template <class Options>
const Options& checked_options(const Options& options, const char* algorithm) {
  const std::vector<OptionIssue> issues = check(options);
  if (!issues.empty())
    throw std::logic_error(std::string(algorithm) + ": invalid options: " + issues.front().field + ": " +
                           issues.front().problem);
  return options;
}

}  // namespace relslam
