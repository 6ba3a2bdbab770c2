// Roll-back control (thesis 4.3.7, Rules 31, 32, 34, walkthrough 4.5): CheckIntervalSize sends
// hints (Rule 32) and SetRollBackTo keeps the earliest request of an iteration. RollBack itself
// (Rule 33: restore a checkpoint, replay the stored inputs with the hints held) is the
// sequencer's, in rlt_xpoints_s.cpp: it restores the whole state and runs iterations again.

#include "roll_back_control.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace relslam::plane {
void set_roll_back_to(std::optional<RollBackEvent>& pending, const RollBackEvent& request) {
  // SetRollBackTo: several requests in one iteration roll back once, to the earliest target.
  if (!pending || request.target_iteration < pending->target_iteration) pending = request;
}

int check_interval_sizes(RltXPointsState& s, const RltXPoint& x, const RollBackOptions& options,
                         RltTemporalHints& hints, std::vector<PlaneId>& failed, std::optional<RollBackEvent>& pending) {
  int sent = 0;
  failed.clear();
  x.check_interval_size(s.planes_, options, s.iteration_, failed);
  for (PlaneId p : failed) {
    RltXPointRef& ref = *s.planes_[p].ref(x.id());
    ref.hinted = true;
    const PlaneIdentity id = s.identity(p);
    // Rule 32: the next level for this plane. Thesis 4.5 (CheckIntervalSize): a plane that
    // started the group it fails in "should not be added to any RltXPoint" — its own new group
    // was the second try, and the replay would only make the same group again.
    const int level = s.founders_[x.id()] == p
                          ? static_cast<int>(HintLevel::NotOnMap)
                          : std::min(hints.count_for(id) + 1, static_cast<int>(HintLevel::NotOnMap));
    hints.add({static_cast<HintLevel>(level), id, ref.join_iteration, x.id()});
    ++sent;
    // Rule 34: back to when the plane joined, so the hint can act there.
    set_roll_back_to(pending, {s.iteration_, ref.join_iteration, p, x.id(), level});
  }
  return sent;
}

}  // namespace relslam::plane
