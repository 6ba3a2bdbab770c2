#pragma once
// Internal to relslam/sim: options that must pass their check() before anything is built.

#include "relslam/core/option_issue.hpp"

namespace relslam::sim {

// `options` itself, or an OptionError naming the first violated constraint: for constructors'
// initialiser lists, so nothing is built from options that fail their check().
template <class Options>
const Options& checked(const Options& options) {
  const std::vector<OptionIssue> issues = check(options);
  if (!issues.empty()) throw OptionError(issues.front().field, issues.front().problem);
  return options;
}

}  // namespace relslam::sim
