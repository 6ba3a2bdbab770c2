#pragma once
// Ground truth that accompanies an ObservationFrame. Only the evaluation layer receives it:
// an algorithm that could read truth could not be shown to ignore it.

#include "relslam/core/rigid.hpp"

#include <vector>

namespace relslam {

struct TruthFrame {
  int iteration = 0;
  Rigid3 world_T_robot;           // true pose; identity at iteration 0 by construction
  bool pose_known = true;         // false for data without a ground-truth path
  std::vector<int> landmark_ids;  // true landmark id of ObservationFrame::points[i]; -1 unknown
  // Where each moving landmark is now, in the order of the truth's dynamic ids (ascending; see
  // eval's LandmarkTruth): the landmark error needs them (thesis 6.5.5 with dynamic points).
  std::vector<Eigen::Vector3d> dynamic_positions;
};

}  // namespace relslam
