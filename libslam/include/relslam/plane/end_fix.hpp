#pragma once
// The pose from planes in one direction and their real ends (beyond the thesis; the adaptive
// preset's pose check, pose_integrity.hpp). Planes that are all parallel fix the heading and the
// position across them but not along them (thesis 4.2.5), which is why the check refuses such a
// pose (PoseReason::OneDirection). Yet an end of a plane in view that the sensor did not cut is
// where the wall ends, a fixed point of the world, and where the map holds that end too (the
// plane was mapped whole, or anchored on that end, Rule 17) it fixes the position along the
// walls. A small frustum looking down a corridor after a dead end's 180-degree turn sees only
// the two parallel sides, cut into pieces whose ends are in view. Part of relslam/plane: Eigen only.

#include "relslam/plane/pose_integrity.hpp"

#include <optional>
#include <span>
#include <utility>

namespace relslam::plane {

// A plane in view on its map plane, with which of the map plane's ends are the wall's own.
struct EndPair {
  LinePair pair;
  bool a_real = false;  // pair.mapped.a is where the wall ends
  bool b_real = false;
};

// The pose that puts every plane of `pairs` (all within min_angle_rad of one direction) on its
// map plane's line and each end the sensor saw uncut (PlaneObject::a_cut, b_cut false) onto its
// map plane's real end: valid (PoseReason::Ends) when at least two such ends agree on the
// position along the walls within offset_bound, none disagrees, every pair agrees with the map
// (agrees()) and the pose follows from `previous` (as check_pose). Otherwise not valid, with the
// reason OneDirection (too few ends), Disagree or Jump.
IntegrityResult fit_pose_to_ends(std::span<const EndPair> pairs, const IntegrityOptions& options,
                                 const std::optional<std::pair<PlanarPose, int>>& previous = std::nullopt);

}  // namespace relslam::plane
