#pragma once
// Everything RltXPointsS carries from one iteration to the next, in one value (thesis 4.4.3.17:
// "the full non-computed state of an iteration", here with the computed part too). A roll-back
// (Rule 33) restores a copy of it and replays, so a member added to the algorithm later is
// restored without anyone having to remember it. Eigen only.

#include "relslam/plane/hints.hpp"
#include "relslam/plane/ids.hpp"
#include "relslam/plane/line_placement.hpp"
#include "relslam/plane/rlt_map_builder.hpp"
#include "relslam/plane/rlt_plane.hpp"
#include "relslam/plane/rlt_xmm_point.hpp"
#include "relslam/plane/rlt_xpoint.hpp"
#include "relslam/plane/rlt_xpoint_link.hpp"

#include <utility>
#include <vector>

namespace relslam::plane {

// RltXPointsS's state, as its base so the member names stay the class's own: a restorable value
// (copy = checkpoint). Per-iteration scratch stays in RltXPointsS.
struct RltXPointsState {
  std::vector<RltPlane> planes_;
  std::vector<RltXPoint> xpoints_;
  std::vector<RltXPointLink> links_;
  std::vector<PlaneId> unassigned_;  // RltPlaneList, creation order
  // Rule 21: planes global matching re-acquired, with the iteration, until they are grouped.
  std::vector<std::pair<PlaneId, int>> reacquired_;
  std::vector<PlaneId> recent_;  // RltPlanes seen within local_match.max_iteration_gap
  std::vector<char> in_recent_;  // per RltPlane: in recent_
  // Per RltPlane: the index of its first observation in that iteration's input (its hint
  // identity with its created iteration, thesis 4.3.7.2).
  std::vector<int> plane_inputs_;
  // Per RltXPoint: the plane it was made for (MakeNewXPoint), kNone for X0 and motion models.
  std::vector<PlaneId> founders_;
  RltMapBuilder builder_;
  RltPoset pose_;
  RltPoset last_valid_pose_;  // Rule 11 places observations with it [R, thesis 4.4.3.11]
  // Adaptive preset: the pose as reported, checked (pose_integrity.hpp); pose_ stays the one the
  // algorithm runs on (Rules 11, 26, 27), the checked pose where that is valid.
  RltPoset checked_pose_;
  RltPoset last_checked_pose_;      // the last valid one ...
  int last_checked_iteration_ = 0;  // ... and its iteration
  // Relocalisation's last find while lost, valid only once a later find confirms it.
  RltPoset recovery_candidate_;
  int recovery_candidate_iteration_ = 0;
  int last_valid_iteration_ = 0;
  // place_by_lines: per RltPlane, where the walls' lines put it (line_placement.hpp).
  std::vector<LinePlacement> line_map_;
  std::vector<RltXMMPoint> motion_models_;
  bool motion_model_active_ = false;  // the last of motion_models_ carries the pose
  int no_pose_count_ = 0;             // Rule 26: iterations without a pose ...
  int no_pose_start_ = 0;             // ... since this one
  XPointId current_ = kNone;          // the current group; the working group while managing
  int iteration_ = 0;
  bool started_ = false;

  // The plane a hint names (thesis 4.3.7.2): its created iteration and its index in that input.
  PlaneIdentity identity(PlaneId plane) const { return {planes_[plane].created_iteration(), plane_inputs_[plane]}; }
};

}  // namespace relslam::plane
