#pragma once
// Internal to libslam/plane: the motion-model control stage (motion_model_control.cpp) as free
// functions on the algorithm's state (thesis 4.3.6: Rules 23–27).

#include "relslam/plane/ids.hpp"
#include "relslam/plane/options.hpp"
#include "relslam/plane/rlt_xpoints_state.hpp"

#include <span>
#include <vector>

namespace relslam::plane {

// What Rule 26's trigger reads of RelativePlaneOptions: the timing, and whether motion models
// are on (part 2 and rules.motion_model).
struct MotionModelStartOptions {
  int start_after;
  int start_window;
  bool enabled;
  static MotionModelStartOptions of(const RelativePlaneOptions& o) {
    return {o.motion_model.start_after, o.motion_model.start_window, o.key_points && o.rules.motion_model};
  }
};

// CheckForMotionModel (Rule 26), in an iteration without a pose: counts it, and gives the plane
// a motion model should start on (kNone: none yet). `assignment`: the RltPlanes in view.
PlaneId check_for_motion_model(RltXPointsState& s, std::span<const PlaneId> assignment,
                               const MotionModelStartOptions& options);
// What CreateMotionModelXPoint reads of RelativePlaneOptions: the track's, ComputeXPoint's and
// BuildMap's.
struct CreateMotionModelOptions {
  const MotionModelOptions& motion_model;
  ComputeXPointOptions compute;
  BuildMapOptions build_map;
  static CreateMotionModelOptions of(const RelativePlaneOptions& o) { return {o.motion_model, o, o}; }
};

// CreateMotionModelXPoint (Rule 27), computed and placed at once.
void create_motion_model(RltXPointsState& s, PlaneId plane, const PlanarPose& world_T_start,
                         const CreateMotionModelOptions& options);
// The active motion model ends when a second plane in view is on the map (the chart's group
// becomes current). `chart` is scratch.
void end_motion_model_on_the_map(RltXPointsState& s, std::span<const PlaneId> assignment, std::vector<int>& chart);

}  // namespace relslam::plane
