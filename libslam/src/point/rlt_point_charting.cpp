#include "relslam/point/rlt_point_charting.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace relslam::point {

void RltPointCharting::begin_iteration(int k) {
  if (started_ && k <= newest_)
    throw std::logic_error("RltPointCharting: iteration " + std::to_string(k) + " after " + std::to_string(newest_));
  if (k < 0) throw std::logic_error("RltPointCharting: negative iteration " + std::to_string(k));
  // Clear every slot skipped since the newest iteration (at most one full turn).
  const int from = started_ ? std::max(newest_ + 1, k - static_cast<int>(slots_.size()) + 1) : k;
  for (int i = from; i <= k; ++i) slots_[slot(i)].clear();
  newest_ = k;
  started_ = true;
}

const std::vector<PointId>& RltPointCharting::at(int k) const {
  static const std::vector<PointId> none;
  if (!started_ || k > newest_ || k < oldest() || k < 0) return none;
  return slots_[slot(k)];
}

void RltPointCharting::enumerate_unique(int a, int b, std::vector<PointId>& out) {
  if (!started_) return;
  a = std::max({a, oldest(), 0});
  b = std::min(b, newest_);
  if (++enumeration_ == 0) {  // wrapped after 4 billion enumerations: restart the stamps
    std::fill(stamp_.begin(), stamp_.end(), 0u);
    enumeration_ = 1;
  }
  for (int k = b; k >= a; --k)
    for (PointId id : slots_[slot(k)]) {
      if (static_cast<std::size_t>(id) >= stamp_.size()) stamp_.resize(static_cast<std::size_t>(id) * 2 + 16, 0u);
      if (stamp_[id] == enumeration_) continue;
      stamp_[id] = enumeration_;
      out.push_back(id);
    }
}

void RltPointCharting::replace(PointId from, PointId to) {
  for (auto& ids : slots_) {
    const bool has_to = std::find(ids.begin(), ids.end(), to) != ids.end();
    for (std::size_t i = 0; i < ids.size(); ++i)
      if (ids[i] == from) {
        if (has_to) {
          ids.erase(ids.begin() + static_cast<std::ptrdiff_t>(i));
        } else {
          ids[i] = to;
        }
        break;
      }
  }
}

}  // namespace relslam::point
