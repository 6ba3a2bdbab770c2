#include "relslam/point/rlt_ungrouped_list.hpp"

#include <stdexcept>
#include <string>

namespace relslam::point {

void RltUngroupedList::push(PointId id, int start) {
  if (contains(id)) return;
  if (!entries_.empty() && start < entries_.back().start)
    throw std::logic_error("RltUngroupedList: start " + std::to_string(start) + " before " +
                           std::to_string(entries_.back().start));
  if (id >= static_cast<PointId>(where_.size())) {
    where_.resize(static_cast<std::size_t>(id) * 2 + 16);
    present_.resize(where_.size(), false);
  }
  where_[id] = entries_.insert(entries_.end(), {id, start});
  present_[id] = true;
}

void RltUngroupedList::remove(PointId id) {
  if (!contains(id)) return;
  entries_.erase(where_[id]);
  present_[id] = false;
}

}  // namespace relslam::point
