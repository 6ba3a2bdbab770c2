#include "relslam/plane/rlt_plane.hpp"

#include <algorithm>
#include <ranges>
#include <stdexcept>
#include <string>
#include <utility>

namespace relslam::plane {

RltPlane::RltPlane(PlaneId id, const PlaneObject& first, int capacity) : id_(id), first_(first), capacity_(capacity) {
  if (capacity < 1) throw std::logic_error("RltPlane: capacity must be >= 1, got " + std::to_string(capacity));
  add(first);
}

void RltPlane::add(const PlaneObject& observation) {
  if (size_ > 0 && observation.iteration <= last_iteration())
    throw std::logic_error("RltPlane::add: plane " + std::to_string(id_) + " got iteration " +
                           std::to_string(observation.iteration) + " after " + std::to_string(last_iteration()));
  intervals_.add(observation.iteration);
  longest_ = std::max(longest_, observation.length());
  if (!observation.a_cut && !observation.b_cut) longest_uncut_ = std::max(longest_uncut_, observation.length());
  if (size_ < capacity_) {
    storage_.push_back(observation);  // still growing: the oldest stays at index 0
    ++size_;
  } else {
    storage_[head_] = observation;  // full: the newest replaces the oldest
    head_ = head_ + 1 < capacity_ ? head_ + 1 : 0;
  }
}

const PlaneObject* RltPlane::get_plane(int iteration) const {
  if (iteration == last_iteration()) return &latest();  // the common question
  const int i = lower_bound(iteration);
  return i < size_ && (*this)[i].iteration == iteration ? &(*this)[i] : nullptr;
}

const RltXPointRef* RltPlane::ref(XPointId x) const {
  const auto it = std::ranges::find(refs_, x, &RltXPointRef::xpoint);
  return it == refs_.end() ? nullptr : &*it;
}

RltXPointRef* RltPlane::ref(XPointId x) { return const_cast<RltXPointRef*>(std::as_const(*this).ref(x)); }

RltXPointRef& RltPlane::join(XPointId x, int iteration) {
  if (ref(x) != nullptr)
    throw std::logic_error("RltPlane::join: plane " + std::to_string(id_) + " is already in X" + std::to_string(x));
  RltXPointRef& joined = refs_.emplace_back();
  joined.xpoint = x;
  joined.join_iteration = iteration;
  return joined;
}

bool RltPlane::add_oneway(XPointId x) {
  if (ref(x) != nullptr || std::ranges::find(oneway_, x) != oneway_.end()) return false;
  oneway_.push_back(x);
  return true;
}

}  // namespace relslam::plane
