#pragma once
// Internal to the algorithms layer: where the robot is expected before Relative Plane matches a
// frame (MotionPredictionOptions in laser_options.hpp says why; the thesis predicts nothing).
// The frame's planes are moved by the prediction P (given relative to the start pose), the
// algorithm estimates C = world_T_(moved frame), which stays near the start pose, and the
// robot's pose is C P. P is the previous frame's pose (the algorithm's where it had one, else
// the previous prediction) composed with the step: the odometry, the last step again or none,
// refined by registering the frame's walls against the previous frames' where asked.

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"
#include "relslam/eval/config/laser_options.hpp"
#include "relslam/scan/wall_registration.hpp"

#include <deque>
#include <optional>
#include <string_view>
#include <vector>

namespace relslam::eval {

// Whose pose a frame reports (iterations.csv's pose_source, with report_prediction).
enum class PoseSource : unsigned char {
  None,        // no pose
  Algorithm,   // the algorithm's
  Prediction,  // the prediction's, the algorithm having none (report_prediction)
};
std::string_view to_string(PoseSource source);

class PosePrediction {
 public:
  PosePrediction(const MotionPredictionOptions& options, const PlanarPose& world_T_start)
      : options_(options), start_(world_T_start) {}

  // The frame the algorithm is given (planes moved by the prediction) and the prediction itself.
  PlaneFrame moved(const PlaneFrame& frame);
  const PlanarPose& prediction() const { return start_T_predicted_; }
  // This frame's wall registration (pairs 0 and not used without one).
  const scan::WallRegistration& registration() const { return registration_; }
  // The step from the previous frame's pose to the prediction.
  const PlanarPose& step() const { return predicted_step_; }
  // The algorithm's pose for the moved frame back as the robot's, and remembered for the next
  // prediction; nothing when the algorithm had none.
  std::optional<PlanarPose> robot_pose(const std::optional<PlanarPose>& world_T_moved);
  PoseSource source() const { return source_; }

 private:
  PlanarPose step_guess(const PlaneFrame& frame) const;
  PlanarPose registered_step(const PlaneFrame& frame, const PlanarPose& guess);

  MotionPredictionOptions options_;
  PlanarPose start_;
  PlanarPose start_T_predicted_;
  PlanarPose previous_;  // start_T_robot of the previous frame (algorithm's, else predicted)
  bool have_previous_ = false;
  PlanarPose step_;  // the last step between two frames' poses
  bool have_step_ = false;
  // The registration's own chain: start_T_robot of the previous frame by registered steps only
  // (the algorithm's corrections of its pose do not move the walls registered against), and the
  // last registration_frames frames' walls in that start frame.
  PlanarPose registered_;
  std::deque<std::vector<PlaneObject>> recent_walls_;
  scan::WallRegistration registration_;
  PlanarPose predicted_step_;
  PoseSource source_ = PoseSource::None;
};

}  // namespace relslam::eval
