#pragma once
// The true landmarks a run is scored against, whatever produced them (simulator or files).
// Where the moving ones are at each iteration travels with the frames (TruthFrame).

#include <Eigen/Core>

#include <vector>

namespace relslam::eval {

struct LandmarkTruth {
  bool known = true;  // false: no ground-truth landmarks, landmark errors are left empty
  // Landmark id i: its position (for a dynamic landmark, at iteration 0).
  std::vector<Eigen::Vector3d> positions;
  // Ascending; TruthFrame::dynamic_positions lists their positions in this order.
  std::vector<int> dynamic_ids;
};

}  // namespace relslam::eval
