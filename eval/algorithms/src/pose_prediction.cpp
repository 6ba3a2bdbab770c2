#include "pose_prediction.hpp"

namespace relslam::eval {

PlaneFrame PosePrediction::moved(const PlaneFrame& frame) {
  ++frames_since_last_;
  if (frame.odometry)
    odometry_since_last_ = odometry_since_last_ * *frame.odometry;
  else
    odometry_complete_ = false;
  // From the last valid pose: the odometry since then where used and complete, else the last
  // step repeated once per frame since that pose, else no motion.
  PlanarPose predicted = last_.value_or(PlanarPose::identity());
  if (last_ && options_.use_odometry && odometry_complete_) {
    predicted = predicted * odometry_since_last_;
  } else if (last_ && options_.constant_velocity && have_step_) {
    for (int i = 0; i < frames_since_last_; ++i) predicted = predicted * step_;
  }
  start_T_predicted_ = predicted;
  PlaneFrame out = frame;
  for (PlaneObject& p : out.planes) {
    const int iteration = p.iteration;
    p = p.transformed(start_T_predicted_);
    p.iteration = iteration;
  }
  return out;
}

std::optional<PlanarPose> PosePrediction::robot_pose(const std::optional<PlanarPose>& world_T_moved) {
  if (!world_T_moved) return std::nullopt;
  const PlanarPose world_T_robot = *world_T_moved * start_T_predicted_;
  const PlanarPose start_T_robot = start_.inverse() * world_T_robot;
  if (last_ && frames_since_last_ == 1) {
    step_ = last_->inverse() * start_T_robot;
    have_step_ = true;
  }
  last_ = start_T_robot;
  frames_since_last_ = 0;
  odometry_since_last_ = PlanarPose::identity();
  odometry_complete_ = true;
  return world_T_robot;
}

}  // namespace relslam::eval
