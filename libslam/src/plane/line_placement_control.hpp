#pragma once
// Internal to libslam/plane: the adaptive preset's line placement after the pose check
// (line_placement_control.cpp, relative_plane.place_by_lines; line_placement.hpp).

#include "relslam/plane/line_placement.hpp"
#include "relslam/plane/options.hpp"
#include "relslam/plane/rlt_xpoints_scratch.hpp"
#include "relslam/plane/rlt_xpoints_state.hpp"

namespace relslam::plane {

// Where the lines of two or more mapped walls fixed this iteration's pose and it passed the check
// (PoseReason::Lines), each other plane in view that no group places adds its observation, put
// into the world by that pose, to s.line_map_ (add_line_evidence).
// `held`: the pose was held along parallel walls (hold_along), which counts too.
void gather_line_evidence(RltXPointsState& s, const RltXPointsScratch& in, const LinePlacementOptions& options,
                          bool held);

// Where the pose check found the mapped planes in view all parallel (PoseReason::OneDirection),
// the pose they fix across them and in heading, with the position along them the frame's as
// handed in (world_T_start: a caller that moved the frame by a motion prediction, so the
// prediction's). Valid, as the motion model's track is (PoseReason::MotionModel: Rules 23-25
// also take the motion along one plane from a model), when every mapped plane in view agrees
// with the map there and the pose is within the robot's reach of the last valid one. True when
// it held the pose.
bool hold_along(RltXPointsState& s, const RltXPointsScratch& in, const IntegrityOptions& options,
                const PlanarPose& world_T_start);

}  // namespace relslam::plane
