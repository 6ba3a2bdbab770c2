#pragma once
// Internal to libslam/em: the extractors' precondition on their options.

#include "relslam/em/options.hpp"

#include <stdexcept>

namespace relslam::em {

// Options reach libslam validated: a violated check here is a bug upstream.
inline void require_valid(const EmOptions& options) {
  const std::vector<OptionIssue> issues = check(options);
  if (!issues.empty())
    throw std::logic_error("EM options not validated: " + issues.front().field + ": " + issues.front().problem);
}

}  // namespace relslam::em
