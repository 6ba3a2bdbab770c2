#pragma once
// RltInterval (thesis 6.4.1): the iterations in which an RltPoint was observed, as runs.

#include <vector>

namespace relslam::point {

// Invariant: runs are sorted, disjoint and separated by at least one missing iteration
// (consecutive iterations always share a run), so counts are exact.
class RltInterval {
 public:
  struct Run {
    int start = 0;
    int end = 0;  // inclusive
  };

  // Appends an iteration after every stored one (the common case: O(1)); a logic_error
  // otherwise, because observations arrive in time order.
  void add(int iteration);
  // Inserts any iteration (a merge copies older observations in); O(runs).
  void insert(int iteration);
  // Number of stored iterations in [a, b]: a binary search, then the overlapping runs.
  int count(int a, int b) const;
  bool contains(int iteration) const { return count(iteration, iteration) == 1; }

  bool empty() const { return runs_.empty(); }
  int first() const { return runs_.front().start; }
  int last() const { return runs_.back().end; }
  int total() const { return total_; }
  const std::vector<Run>& runs() const { return runs_; }

 private:
  std::vector<Run> runs_;
  int total_ = 0;
};

}  // namespace relslam::point
