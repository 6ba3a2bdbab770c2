#pragma once
// Internal to the algorithms layer: where the robot is expected before Relative Plane matches a
// frame (MotionPredictionOptions in laser_options.hpp says why; the thesis predicts nothing).
// The frame's planes are moved by the prediction P (given relative to the start pose), the
// algorithm estimates C = world_T_(moved frame), which stays near the start pose, and the
// robot's pose is C P.

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"
#include "relslam/eval/config/laser_options.hpp"

#include <optional>

namespace relslam::eval {

class PosePrediction {
 public:
  PosePrediction(const MotionPredictionOptions& options, const PlanarPose& world_T_start)
      : options_(options), start_(world_T_start) {}

  // The frame the algorithm is given (planes moved by the prediction) and the prediction itself.
  PlaneFrame moved(const PlaneFrame& frame);
  const PlanarPose& prediction() const { return start_T_predicted_; }
  // The algorithm's pose for the moved frame back as the robot's, and remembered for the next
  // prediction; nothing when the algorithm had none.
  std::optional<PlanarPose> robot_pose(const std::optional<PlanarPose>& world_T_moved);

 private:
  MotionPredictionOptions options_;
  PlanarPose start_;
  PlanarPose start_T_predicted_;
  std::optional<PlanarPose> last_;  // start_T_robot at the last valid pose
  PlanarPose step_;                 // the last step between two consecutive valid poses
  int frames_since_last_ = 0;       // frames since last_
  bool have_step_ = false;
  PlanarPose odometry_since_last_;  // the odometry composed since last_
  bool odometry_complete_ = true;   // every frame since last_ had odometry
};

}  // namespace relslam::eval
