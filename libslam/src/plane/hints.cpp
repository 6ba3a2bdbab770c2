#include "relslam/plane/hints.hpp"

#include <algorithm>

namespace relslam::plane {

void RltTemporalHints::add(const RltTemporalHint& hint) {
  // Thesis 4.4.3.16: later hints came from a replay the new one changes; they may not hold.
  std::erase_if(hints_, [&](const RltTemporalHint& h) { return h.iteration > hint.iteration; });
  hints_.push_back(hint);
}

int RltTemporalHints::count_for(const PlaneIdentity& plane) const {
  return static_cast<int>(std::ranges::count(hints_, plane, &RltTemporalHint::plane));
}

bool RltTemporalHints::may_join(const PlaneIdentity& plane, int iteration, XPointId x) const {
  return std::ranges::none_of(hints_, [&](const RltTemporalHint& h) {
    if (h.plane != plane || h.iteration > iteration) return false;
    return h.level != HintLevel::NotInX || h.xpoint == x;
  });
}

bool RltTemporalHints::may_start_group(const PlaneIdentity& plane, int iteration) const {
  return std::ranges::none_of(hints_, [&](const RltTemporalHint& h) {
    return h.plane == plane && h.iteration <= iteration && h.level == HintLevel::NotOnMap;
  });
}

}  // namespace relslam::plane
