#pragma once
// Scoring a planar path where there is no ground truth (a recorded log): against another
// algorithm's path taken as the reference (ICP-SLAM's, as MRPT's own icp-slam maps the log),
// and by the gap it leaves where the robot revisits a place.

#include "relslam/core/planar_pose.hpp"

#include <optional>
#include <vector>

namespace relslam::eval {

struct ReferencePathError {
  int pairs = 0;       // frames where both paths have a pose
  double ate = 0;      // RMS of the position differences after the alignment (0 without pairs)
  double max = 0;      // the largest of them
  double rotation_deg = 0;  // of the alignment estimate -> reference
};

// ATE of `estimate` against `reference` (paired by index, a missing pose on either side skips
// the frame) after the 2-D rigid least-squares alignment of its positions onto the reference's:
// the two may start in different frames. Fewer than 2 pairs: the positions as they are.
ReferencePathError ate_vs_reference(const std::vector<std::optional<PlanarPose>>& estimate,
                                    const std::vector<std::optional<PlanarPose>>& reference);

struct LoopGap {
  double distance = 0;     // map units
  double heading_deg = 0;  // absolute, (0, 180]
};

// The gap the path leaves between frames `first` and `second`, where the robot stands at the
// same place: the motion the path claims from one to the other, less the reference's where one
// is given (the place is only roughly the same), else as it is. None when a pose is missing or
// a frame lies outside the path.
std::optional<LoopGap> loop_gap(const std::vector<std::optional<PlanarPose>>& path, int first, int second,
                                const std::vector<std::optional<PlanarPose>>* reference = nullptr);

}  // namespace relslam::eval
