#include "relslam/point/rlt_point.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace relslam::point {

int compare(const Point& a, const Point& b, double bound, int max_gap) {
  if (std::abs(a.iteration - b.iteration) > max_gap) return -1;
  const double d = (a.p - b.p).norm();
  if (!(d <= bound)) return -1;
  return static_cast<int>(std::lround(100.0 * (1.0 - d / bound)));
}

void ObservationRing::push(const Point& observation) {
  if (size_ > 0 && observation.iteration <= latest().iteration)
    throw std::logic_error("ObservationRing::push: iteration " + std::to_string(observation.iteration) + " after " +
                           std::to_string(latest().iteration));
  if (static_cast<int>(buffer_.size()) < capacity_) {
    buffer_.push_back(observation);  // still growing: head stays 0
    ++size_;
    return;
  }
  buffer_[head_] = observation;  // full: overwrite the oldest
  head_ = head_ + 1 == capacity_ ? 0 : head_ + 1;
}

int ObservationRing::lower_bound(int iteration) const {
  int lo = 0, hi = size_;
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    if ((*this)[mid].iteration < iteration)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo;
}

const Point* ObservationRing::at(int iteration) const {
  if (size_ == 0 || latest().iteration < iteration) return nullptr;  // not seen since
  if (latest().iteration == iteration) return &latest();               // the usual question
  const int i = lower_bound(iteration);
  return i < size_ && (*this)[i].iteration == iteration ? &(*this)[i] : nullptr;
}

}  // namespace relslam::point
