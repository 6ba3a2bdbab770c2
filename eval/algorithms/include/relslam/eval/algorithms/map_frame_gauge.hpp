#pragma once
// Where the evaluation puts Relative Point's map frame. The map frame is the robot's frame at
// the mapper's first iteration (thesis 6.3.3), where the truth's world frame also starts. When
// the adaptive preset moves it to a later frame (a sparse start), the evaluation
// places it at the robot's true pose there: the same gauge, one frame later. The algorithm never
// sees it; the run's scoring and `relslam render` both go through this one class.

#include "relslam/core/rigid.hpp"
#include "relslam/core/truth.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <optional>

namespace relslam::eval {

class MapFrameGauge {
 public:
  // After each step: `map_frame_iteration` is the mapper's first_iteration() now.
  void observe(int iteration, int map_frame_iteration, const TruthFrame& truth) {
    if (map_frame_iteration == iteration && iteration > start_) {
      if (truth.pose_known) world_T_map_ = truth.world_T_robot;
      steps_before_ = steps_;
    }
    start_ = std::min(start_, iteration);
    ++steps_;
  }

  Rigid3 pose(const Rigid3& map_T_robot) const { return world_T_map_ ? *world_T_map_ * map_T_robot : map_T_robot; }
  Eigen::Vector3d point(const Eigen::Vector3d& p_map) const { return world_T_map_ ? *world_T_map_ * p_map : p_map; }
  // Steps before the map frame: no pose existed there.
  std::size_t steps_before() const { return steps_before_; }

 private:
  // Unset while the map frame is the first iteration's: the estimates pass through untouched
  // (bit for bit, as before the adaptive preset).
  std::optional<Rigid3> world_T_map_;
  int start_ = std::numeric_limits<int>::max();
  std::size_t steps_ = 0, steps_before_ = 0;
};

}  // namespace relslam::eval
