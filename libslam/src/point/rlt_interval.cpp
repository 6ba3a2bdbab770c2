#include "relslam/point/rlt_interval.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace relslam::point {

void RltInterval::add(int iteration) {
  if (!runs_.empty() && iteration <= runs_.back().end)
    throw std::logic_error("RltInterval::add: iteration " + std::to_string(iteration) + " after " +
                           std::to_string(runs_.back().end));
  if (!runs_.empty() && iteration == runs_.back().end + 1)
    runs_.back().end = iteration;
  else
    runs_.push_back({iteration, iteration});
  ++total_;
}

void RltInterval::insert(int iteration) {
  if (runs_.empty() || iteration > runs_.back().end) return add(iteration);
  // First run ending at or after the iteration.
  auto it = std::lower_bound(runs_.begin(), runs_.end(), iteration, [](const Run& r, int i) { return r.end < i; });
  if (it->start <= iteration) return;  // already there
  ++total_;
  const bool joins_next = it->start == iteration + 1;
  const bool joins_previous = it != runs_.begin() && std::prev(it)->end == iteration - 1;
  if (joins_previous && joins_next) {
    std::prev(it)->end = it->end;
    runs_.erase(it);
  } else if (joins_previous) {
    std::prev(it)->end = iteration;
  } else if (joins_next) {
    it->start = iteration;
  } else {
    runs_.insert(it, {iteration, iteration});
  }
}

int RltInterval::count(int a, int b) const {
  if (b < a) return 0;
  auto it = std::lower_bound(runs_.begin(), runs_.end(), a, [](const Run& r, int i) { return r.end < i; });
  int n = 0;
  for (; it != runs_.end() && it->start <= b; ++it) n += std::min(it->end, b) - std::max(it->start, a) + 1;
  return n;
}

}  // namespace relslam::point
