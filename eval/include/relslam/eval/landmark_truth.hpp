#pragma once
// The true landmarks a run is scored against, whatever produced them (simulator or files).

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace relslam::eval {

struct LandmarkTruth {
  bool known = true;  // false: no ground-truth landmarks, landmark errors are left empty
  // Landmark id i: its position (for a dynamic landmark, at iteration 0).
  std::vector<Eigen::Vector3d> positions;
  std::vector<int> dynamic_ids;  // ascending
  // Where dynamic landmark `id` is at iteration k (needed only when dynamic_ids is not empty).
  std::function<Eigen::Vector3d(int id, int k)> dynamic_position;
};

}  // namespace relslam::eval
