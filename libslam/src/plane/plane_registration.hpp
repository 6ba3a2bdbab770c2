#pragma once
// Internal to libslam/plane: the registration stage (plane_registration.cpp, AddPlane: thesis
// 4.2.1, 4.2.2; Rules 1, 10, 11) as free functions on the algorithm's state and its
// per-iteration scratch.

#include "relslam/plane/ids.hpp"
#include "relslam/plane/options.hpp"
#include "relslam/plane/relative_plane_step.hpp"
#include "relslam/plane/rlt_xpoints_scratch.hpp"
#include "relslam/plane/rlt_xpoints_state.hpp"

#include <utility>
#include <vector>

namespace relslam::plane {

// What registration reads of RelativePlaneOptions.
struct RegistrationOptions {
  const MatchBounds& local_match;   // Rule 1: MatchPlane against the previous observation
  const MatchBounds& global_match;  // Rule 11: MatchPlanetoMap
  bool local_registration;          // Rule 1 for mapped RltPlanes (off: those only through the pose)
  bool global_matching;             // Rule 11
  bool normal_direction;            // Rule 10
  int plane_capacity;               // a new RltPlane's observation array
  // Rule 11's pose: the motion model's track, or GetPoset from what Rule 1 registered.
  const MotionModelOptions& motion_model;
  GetPosetOptions get_poset;
  static RegistrationOptions of(const RelativePlaneOptions& o) {
    return {o.local_match,
            o.global_match,
            o.rules.local_registration,
            o.rules.global_matching,
            o.rules.normal_direction,
            o.plane_capacity,
            o.motion_model,
            o};
  }
};

// AddPlane for every observation of `frame`: Rule 1, Rule 11, then new RltPlanes; the frame's
// planes and their RltPlanes are left in `in` (stamped_, assignment_). Counts into `result`.
void add_planes(RltXPointsState& s, RltXPointsScratch& in, const PlaneFrame& frame, const RegistrationOptions& options,
                RelativePlaneStep& result);

}  // namespace relslam::plane
