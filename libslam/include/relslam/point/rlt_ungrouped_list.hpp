#pragma once
// RltUngroupedList (thesis 6.4.2): RltPoints waiting to be grouped at one level, oldest first.

#include "relslam/point/rlt_point.hpp"

#include <list>
#include <vector>

namespace relslam::point {

// Invariant: entries are in non-decreasing start order and each id appears at most once.
// A std::list, as in the thesis, for O(1) removal of a grouped point from the middle.
class RltUngroupedList {
 public:
  struct Entry {
    PointId id;
    int start;  // iteration its visible run began: creation, or a return after being lost
  };

  void push(PointId id, int start);
  bool contains(PointId id) const { return id >= 0 && id < static_cast<PointId>(present_.size()) && present_[id]; }
  void remove(PointId id);
  bool empty() const { return entries_.empty(); }
  const Entry& front() const { return entries_.front(); }
  void pop_front() { remove(entries_.front().id); }
  std::size_t size() const { return entries_.size(); }

 private:
  std::list<Entry> entries_;
  std::vector<std::list<Entry>::iterator> where_;  // by id, valid where present_
  std::vector<bool> present_;
};

}  // namespace relslam::point
