#pragma once
// RltPlaneInterval (thesis 4.4.3.8; thesis 4.3.3): the iterations an RltPlane was seen in, as
// runs — a plane can leave the view and come back (backtracking, loop closing).

#include "relslam/plane/rlt_interval.hpp"

#include <vector>

namespace relslam::plane {

// Invariant: runs are sorted, disjoint and separated by at least one iteration without an
// observation (thesis 4.3.3: any missing iteration ends a run), so total_size() is exact.
class RltPlaneInterval {
 public:
  // AddInterval for one new observation: extends the last run or starts a new one; a
  // logic_error unless `iteration` comes after every stored one (observations arrive in order).
  void add(int iteration);
  bool in_interval(int iteration) const;
  int total_size() const { return total_; }
  bool empty() const { return runs_.empty(); }
  int first() const { return runs_.front().start; }
  int last() const { return runs_.back().end; }
  // Enumerate: the runs, oldest first.
  const std::vector<RltInterval>& runs() const { return runs_; }
  void clear() {
    runs_.clear();
    total_ = 0;
  }

  // GetMinimumInterval: the iterations in both lists (Rule 7's common interval is the
  // minimum interval of all of a group's planes). Writes into `out` to reuse its storage.
  static void minimum_interval(const RltPlaneInterval& a, const RltPlaneInterval& b, RltPlaneInterval& out);
  // |a ∩ b| without building it.
  static int common_size(const RltPlaneInterval& a, const RltPlaneInterval& b);

 private:
  std::vector<RltInterval> runs_;
  int total_ = 0;
};

}  // namespace relslam::plane
