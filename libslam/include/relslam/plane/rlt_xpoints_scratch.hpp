#pragma once
// The Relative Plane algorithm's per-iteration scratch (RltXPointsS's second base), handed to
// its stages: in its own header below the sequencer and the stages that share it.

#include "relslam/core/plane_object.hpp"
#include "relslam/plane/ids.hpp"
#include "relslam/plane/rlt_map_builder.hpp"
#include "relslam/plane/rlt_plane_interval.hpp"

#include <vector>

namespace relslam::plane {

// RltXPointsS's per-iteration scratch, as its base like RltXPointsState (so the member names
// stay the class's own) and a value the stages can be handed: this iteration's planes in view
// and what AddPlane did with them, and ManageXPoints's working buffers. Kept from one iteration
// to the next only to avoid allocations; never restored.
struct RltXPointsScratch {
  std::vector<PlaneObject> stamped_;  // the frame's planes with their iteration set
  std::vector<PlaneId> assignment_;   // the RltPlane of each, in input order
  std::vector<char> taken_;           // per RltPlane: registered this iteration
  std::vector<PlaneMatch> matches_;
  std::vector<PlaneId> reacquired_now_;  // Rule 11 this iteration
  std::vector<RegisteredObservation> registered_;
  // ManageXPoints's.
  std::vector<int> chart_;  // Rule 22: planes in view per group
  std::vector<char> visited_;
  std::vector<XPointId> stack_;
  std::vector<PlaneId> candidates_;
  RltPlaneInterval scratch_interval_;
};

}  // namespace relslam::plane
