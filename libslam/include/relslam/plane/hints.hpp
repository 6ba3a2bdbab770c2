#pragma once
// RltTemporalHint / RltTemporalHints (thesis 4.4.3.15–16, Rules 32 and 34; thesis 4.3.7.2):
// what a roll-back sends back in time, so the replay does not repeat what went wrong. Eigen-free
// values; the algorithm asks them before it puts a plane into a group.

#include "relslam/plane/ids.hpp"

#include <compare>
#include <vector>

namespace relslam::plane {

// A plane as a hint names it: the iteration its RltPlane was created and the index of that first
// observation in the iteration's input (thesis 4.3.7.2). RltPlane ids are not stable across a
// replay (a plane grouped differently can change what global matching creates later); this is,
// because the stored inputs replay in the same order.
struct PlaneIdentity {
  int created_iteration = 0;
  int input_index = 0;
  auto operator<=>(const PlaneIdentity&) const = default;
};

// Rule 32's three levels, in the order a plane gets them (thesis 4.3.7.2).
enum class HintLevel : unsigned char {
  NotInX = 1,       // not into that group: on replay the plane tries the adjacent groups, else a new one
  NoExistingX = 2,  // into no existing group: only a group of its own
  NotOnMap = 3,     // into no group at all: the plane is left out of the map
};

struct RltTemporalHint {
  HintLevel level = HintLevel::NotInX;
  PlaneIdentity plane;
  int iteration = 0;         // it applies from this iteration on (the membership's join iteration)
  XPointId xpoint = kNone;   // NotInX: the group the plane must not join
};

// Invariant: hints are kept in the order they were added, and none has an iteration later than
// the last one added — adding a hint deletes every hint with a later iteration, since the replay
// from the earlier one may not lead there again (thesis 4.4.3.16). A roll-back can so set off
// others before the run settles.
class RltTemporalHints {
 public:
  void add(const RltTemporalHint& hint);
  // Hints held for `plane` (the level its next one gets is this + 1, at most NotOnMap).
  int count_for(const PlaneIdentity& plane) const;

  // CanAddToXPoint: `plane` may join the existing group `x` at `iteration` (not NotInX(x), not
  // NoExistingX, not NotOnMap).
  bool may_join(const PlaneIdentity& plane, int iteration, XPointId x) const;
  // CanMakeNewXPoint: `plane` may start a group of its own at `iteration` (not NotOnMap).
  bool may_start_group(const PlaneIdentity& plane, int iteration) const;

  const std::vector<RltTemporalHint>& all() const { return hints_; }
  bool empty() const { return hints_.empty(); }

 private:
  std::vector<RltTemporalHint> hints_;
};

}  // namespace relslam::plane
