#pragma once
// RltPointCharting (thesis 6.2.3): which RltPoints were seen in each recent iteration.

#include "relslam/point/rlt_point.hpp"

#include <vector>

namespace relslam::point {

// A circular array of per-iteration id lists covering the last `capacity` iterations, plus every
// id in order of its latest sighting (newest first), so "seen since iteration a" is a prefix.
// Invariant: iterations begin in increasing order; ids within one iteration are distinct; the
// recency list holds each id once, in non-increasing order of the newest slot holding it.
class RltPointCharting {
 public:
  explicit RltPointCharting(int capacity = 512) : slots_(static_cast<std::size_t>(capacity)) {}

  // Starts iteration k (> the newest so far), forgetting the one `capacity` iterations back.
  void begin_iteration(int k);
  void add(PointId id);
  // Ids seen at iteration k; empty when k is outside the window.
  const std::vector<PointId>& at(int k) const;
  // Every id seen in [a, b] ∩ window exactly once, appended to `out` in no promised order
  // (callers rank or index what they get). When nothing was seen after b, O(ids returned)
  // through the recency list: group planning asks for the whole look-back and look-ahead
  // window, up to 121 iterations of up to ~540 sightings each (thesis 6.4.3). Otherwise
  // O(ids visited): a stamp per id replaces the thesis's hash table of seen indexes.
  void enumerate_unique(int a, int b, std::vector<PointId>& out);
  // Replaces `from` by `to` in every stored list (a merge, thesis 6.5.2).
  void replace(PointId from, PointId to);

  int newest() const { return newest_; }
  int oldest() const { return newest_ - static_cast<int>(slots_.size()) + 1; }

 private:
  std::size_t slot(int k) const { return static_cast<std::size_t>(k) % slots_.size(); }
  void grow(PointId id);  // room in the recency list for ids up to `id`
  void unlink(PointId id);
  void link_after(PointId id, PointId before);  // kNone: at the front
  std::vector<std::vector<PointId>> slots_;
  int newest_ = -1;
  bool started_ = false;
  std::vector<unsigned> stamp_;  // per id: the enumeration that last returned it
  // The recency list, intrusive over ids: latest_[id] is the newest iteration holding it (kNone:
  // not listed), newer_/older_ its neighbours.
  std::vector<int> latest_;
  std::vector<PointId> newer_, older_;
  PointId front_ = kNone;
  unsigned enumeration_ = 0;
};

}  // namespace relslam::point
