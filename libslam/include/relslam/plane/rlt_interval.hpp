#pragma once
// RltInterval (thesis 4.4.3.7; thesis 4.3.3): one span of iterations, both ends inclusive.

#include <algorithm>

namespace relslam::plane {

struct RltInterval {
  int start = 0;
  int end = -1;  // inclusive; end < start is the empty interval

  int size() const { return end < start ? 0 : end - start + 1; }
  bool empty() const { return end < start; }
  bool in_interval(int iteration) const { return start <= iteration && iteration <= end; }
  // MergeInterval (the thesis's "or"): the smallest interval holding both.
  RltInterval merge(const RltInterval& other) const {
    if (empty()) return other;
    if (other.empty()) return *this;
    return {std::min(start, other.start), std::max(end, other.end)};
  }
  // Shrink (the thesis's "and"): the iterations in both.
  RltInterval shrink(const RltInterval& other) const {
    return {std::max(start, other.start), std::min(end, other.end)};
  }
};

}  // namespace relslam::plane
