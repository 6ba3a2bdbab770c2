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

void RltPointCharting::add(PointId id) {
  slots_[slot(newest_)].push_back(id);
  grow(id);
  if (latest_[id] != kNone) unlink(id);
  link_after(id, kNone);
  latest_[id] = newest_;
}

void RltPointCharting::grow(PointId id) {
  if (static_cast<std::size_t>(id) < latest_.size()) return;
  const std::size_t size = static_cast<std::size_t>(id) * 2 + 16;
  latest_.resize(size, kNone);
  newer_.resize(size, kNone);
  older_.resize(size, kNone);
}

void RltPointCharting::unlink(PointId id) {
  (newer_[id] == kNone ? front_ : older_[newer_[id]]) = older_[id];
  if (older_[id] != kNone) newer_[older_[id]] = newer_[id];
  newer_[id] = older_[id] = kNone;
}

void RltPointCharting::link_after(PointId id, PointId before) {
  PointId& next = before == kNone ? front_ : older_[before];
  older_[id] = next;
  newer_[id] = before;
  if (next != kNone) newer_[next] = id;
  next = id;
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
  if (a > b) return;
  bool seen_after_b = false;
  for (int k = std::max(b + 1, oldest()); k <= newest_ && !seen_after_b; ++k) seen_after_b = !slots_[slot(k)].empty();
  if (!seen_after_b) {
    for (PointId id = front_; id != kNone && latest_[id] >= a; id = older_[id]) out.push_back(id);
    return;
  }
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
  // `to` is now seen wherever `from` was: it takes from's place in the recency list if that is
  // newer than its own.
  const auto listed = [&](PointId id) { return static_cast<std::size_t>(id) < latest_.size() && latest_[id] != kNone; };
  if (listed(from)) {
    if (!listed(to) || latest_[to] < latest_[from]) {
      if (listed(to)) unlink(to);
      grow(to);
      link_after(to, newer_[from]);
      latest_[to] = latest_[from];
    }
    unlink(from);
    latest_[from] = kNone;
  }
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
