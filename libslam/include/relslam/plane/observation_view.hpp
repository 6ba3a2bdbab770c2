#pragma once
// One plane's observations in iteration order, read where they are stored (thesis 4.4.3.4,
// GetPlane): a span, or the two contiguous pieces of RltPlane's circular array once it has
// wrapped. The comparisons (Rules 13–19) read a plane's history through this view, so nothing
// copies a whole history to compare one growth phase. Part of relslam/plane: Eigen only.

#include "relslam/core/plane_object.hpp"

#include <span>
#include <vector>

namespace relslam::plane {

class ObservationView {
 public:
  ObservationView() = default;
  ObservationView(std::span<const PlaneObject> all) : head_(all) {}  // NOLINT: a span is a view
  ObservationView(const std::vector<PlaneObject>& all) : head_(all) {}  // NOLINT
  // `head` then `tail`: the older observations first.
  ObservationView(std::span<const PlaneObject> head, std::span<const PlaneObject> tail) : head_(head), tail_(tail) {}

  int size() const { return static_cast<int>(head_.size() + tail_.size()); }
  bool empty() const { return size() == 0; }
  const PlaneObject& operator[](int i) const {
    const int h = static_cast<int>(head_.size());
    return i < h ? head_[i] : tail_[i - h];
  }
  // Index of the first observation at or after `iteration` (size() if none): binary search.
  int lower_bound(int iteration) const {
    int first = 0, last = size();
    while (first < last) {
      const int middle = first + (last - first) / 2;
      if ((*this)[middle].iteration < iteration)
        first = middle + 1;
      else
        last = middle;
    }
    return first;
  }
  // Appends observations [first, first + count) to `out`.
  void copy(int first, int count, std::vector<PlaneObject>& out) const {
    for (int i = first; i < first + count; ++i) out.push_back((*this)[i]);
  }

 private:
  std::span<const PlaneObject> head_, tail_;
};

}  // namespace relslam::plane
