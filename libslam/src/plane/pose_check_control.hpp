#pragma once
// Internal to libslam/plane: the adaptive preset's pose check after GetPoset
// (pose_check_control.cpp): the pose from the planes' lines with its integrity check
// (pose_integrity.hpp), the motion model in its stated case, and relocalisation when lost.

#include "relslam/plane/options.hpp"
#include "relslam/plane/rlt_xpoints_scratch.hpp"
#include "relslam/plane/rlt_xpoints_state.hpp"

#include <vector>

namespace relslam::plane {

// Sets s.checked_pose_, the pose reported, from the observations in `in`, after GetPoset and
// the motion model set s.pose_; a valid checked pose also becomes s.pose_ and the last valid
// pose the algorithm runs on (Rules 11, 27).
void check_poset(RltXPointsState& s, const RltXPointsScratch& in, const IntegrityOptions& options);

// The observations of this iteration whose RltPlane is on the map, with their map planes.
std::vector<LinePair> line_pairs(const RltXPointsState& s, const RltXPointsScratch& in);

}  // namespace relslam::plane
