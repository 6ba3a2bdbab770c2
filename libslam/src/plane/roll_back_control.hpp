#pragma once
// Internal to libslam/plane: the parts of roll-back control (roll_back_control.cpp; thesis 4.3.7,
// Rules 31–34) that need no replay: CheckIntervalSize and SetRollBackTo. RollBack itself stays
// with RltXPointsS, as it restores the whole state and runs iterations again.

#include "relslam/plane/hints.hpp"
#include "relslam/plane/ids.hpp"
#include "relslam/plane/options.hpp"
#include "relslam/plane/rlt_xpoint.hpp"
#include "relslam/plane/rlt_xpoints_state.hpp"
#include "relslam/plane/roll_back.hpp"

#include <optional>
#include <vector>

namespace relslam::plane {

// SetRollBackTo: several requests in one iteration roll back once, to the earliest target.
void set_roll_back_to(std::optional<RollBackEvent>& pending, const RollBackEvent& request);

// CheckIntervalSize (Rules 31, 32) after ComputeXPoint of `x`: each plane whose membership
// failed is marked hinted, gets Rule 32's next hint in `hints`, and asks for the roll-back to
// when it joined (Rule 34). Returns the hints sent; `failed` is scratch.
int check_interval_sizes(RltXPointsState& s, const RltXPoint& x, const RollBackOptions& options,
                         RltTemporalHints& hints, std::vector<PlaneId>& failed, std::optional<RollBackEvent>& pending);

}  // namespace relslam::plane
