#pragma once
// RltPointCharting (thesis 6.2.3): which RltPoints were seen in each recent iteration.

#include "relslam/point/rlt_point.hpp"

#include <vector>

namespace relslam::point {

// A circular array of per-iteration id lists covering the last `capacity` iterations.
// Invariant: iterations begin in increasing order; ids within one iteration are distinct.
class RltPointCharting {
 public:
  explicit RltPointCharting(int capacity = 512) : slots_(static_cast<std::size_t>(capacity)) {}

  // Starts iteration k (> the newest so far), forgetting the one `capacity` iterations back.
  void begin_iteration(int k);
  void add(PointId id) { slots_[slot(newest_)].push_back(id); }
  // Ids seen at iteration k; empty when k is outside the window.
  const std::vector<PointId>& at(int k) const;
  // Every id seen in [a, b] ∩ window exactly once, newest iterations first, appended to `out`.
  // O(ids visited): a stamp per id replaces the thesis's hash table of seen indexes.
  void enumerate_unique(int a, int b, std::vector<PointId>& out);
  // Replaces `from` by `to` in every stored list (a merge, thesis 6.5.2).
  void replace(PointId from, PointId to);

  int newest() const { return newest_; }
  int oldest() const { return newest_ - static_cast<int>(slots_.size()) + 1; }

 private:
  std::size_t slot(int k) const { return static_cast<std::size_t>(k) % slots_.size(); }
  std::vector<std::vector<PointId>> slots_;
  int newest_ = -1;
  bool started_ = false;
  std::vector<unsigned> stamp_;  // per id: the enumeration that last returned it
  unsigned enumeration_ = 0;
};

}  // namespace relslam::point
