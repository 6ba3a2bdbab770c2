#include "relslam/plane/rlt_plane_interval.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace relslam::plane {
namespace {

// The nested enumeration of GetMinimumInterval as one merge walk over two sorted run lists:
// `visit` gets each non-empty intersection of a run of `a` with a run of `b`, in order.
template <class Visit>
void for_each_common_run(const RltPlaneInterval& a, const RltPlaneInterval& b, Visit visit) {
  auto i = a.runs().begin(), j = b.runs().begin();
  while (i != a.runs().end() && j != b.runs().end()) {
    const RltInterval common = i->shrink(*j);
    if (!common.empty()) visit(common);
    // The run that ends first cannot meet anything further in the other list.
    if (i->end < j->end)
      ++i;
    else
      ++j;
  }
}

}  // namespace

void RltPlaneInterval::add(int iteration) {
  const RltInterval seen{iteration, iteration};
  if (runs_.empty()) {
    runs_.push_back(seen);
  } else if (RltInterval& newest = runs_.back(); iteration <= newest.end) {
    throw std::logic_error("RltPlaneInterval::add: iteration " + std::to_string(iteration) + " is not after " +
                           std::to_string(newest.end));
  } else if (iteration == newest.end + 1) {
    newest = newest.merge(seen);  // the next iteration continues the run
  } else {
    runs_.push_back(seen);  // a missing iteration ends it
  }
  ++total_;
}

bool RltPlaneInterval::in_interval(int iteration) const {
  // The first run ending at or after `iteration` is the only one that can hold it.
  const auto run = std::ranges::lower_bound(runs_, iteration, {}, &RltInterval::end);
  return run != runs_.end() && run->start <= iteration;
}

void RltPlaneInterval::minimum_interval(const RltPlaneInterval& a, const RltPlaneInterval& b, RltPlaneInterval& out) {
  out.clear();
  for_each_common_run(a, b, [&out](const RltInterval& common) {
    out.runs_.push_back(common);
    out.total_ += common.size();
  });
}

int RltPlaneInterval::common_size(const RltPlaneInterval& a, const RltPlaneInterval& b) {
  int size = 0;
  for_each_common_run(a, b, [&size](const RltInterval& common) { size += common.size(); });
  return size;
}

}  // namespace relslam::plane
