#include "pose_prediction.hpp"

namespace relslam::eval {
namespace {

std::vector<PlaneObject> moved_by(const std::vector<PlaneObject>& planes, const PlanarPose& a_T_b) {
  std::vector<PlaneObject> out;
  out.reserve(planes.size());
  for (const PlaneObject& p : planes) {
    PlaneObject m = p.transformed(a_T_b);
    m.iteration = p.iteration;
    out.push_back(m);
  }
  return out;
}

}  // namespace

// The step since the previous frame before any registration: the odometry where used and
// present, else the last step repeated where asked, else none.
PlanarPose PosePrediction::step_guess(const PlaneFrame& frame) const {
  if (options_.use_odometry && frame.odometry) return *frame.odometry;
  if (options_.constant_velocity && have_step_) return step_;
  return PlanarPose::identity();
}

// The step refined by registering the frame's walls against the recent frames' (in the
// registration's start frame), and the recent walls updated.
PlanarPose PosePrediction::registered_step(const PlaneFrame& frame, const PlanarPose& guess) {
  std::vector<PlaneObject> target;
  for (const std::vector<PlaneObject>& walls : recent_walls_) target.insert(target.end(), walls.begin(), walls.end());
  registration_ = scan::register_walls(target, frame.planes, registered_ * guess, options_.registration);
  const PlanarPose step = registered_.inverse() * registration_.previous_T_current;
  registered_ = registration_.previous_T_current;
  recent_walls_.push_back(moved_by(frame.planes, registered_));
  while (static_cast<int>(recent_walls_.size()) > options_.registration_frames) recent_walls_.pop_front();
  return step;
}

PlaneFrame PosePrediction::moved(const PlaneFrame& frame) {
  PlanarPose step = step_guess(frame);
  registration_ = {};
  if (options_.register_walls) {
    if (have_previous_)
      step = registered_step(frame, step);
    else
      recent_walls_.push_back(frame.planes);
  }
  predicted_step_ = step;
  start_T_predicted_ = have_previous_ ? previous_ * step : PlanarPose::identity();
  PlaneFrame out = frame;
  out.planes = moved_by(frame.planes, start_T_predicted_);
  return out;
}

std::string_view to_string(PoseSource source) {
  switch (source) {
    case PoseSource::Algorithm:
      return "algorithm";
    case PoseSource::Prediction:
      return "prediction";
    case PoseSource::None:
      break;
  }
  return "none";
}

std::optional<PlanarPose> PosePrediction::robot_pose(const std::optional<PlanarPose>& world_T_moved) {
  // Without the algorithm's pose the prediction stands in for the next frame's.
  const PlanarPose start_T_robot =
      world_T_moved ? start_.inverse() * (*world_T_moved * start_T_predicted_) : start_T_predicted_;
  // The velocity: the registered step where the walls gave one (the algorithm's corrections of
  // a drifting pose are no motion), else the step between the two poses.
  if (registration_.used) {
    step_ = predicted_step_;
    have_step_ = true;
  } else if (have_previous_) {
    step_ = previous_.inverse() * start_T_robot;
    have_step_ = true;
  }
  previous_ = start_T_robot;
  have_previous_ = true;
  source_ = world_T_moved ? PoseSource::Algorithm
                          : (options_.report_prediction ? PoseSource::Prediction : PoseSource::None);
  if (source_ == PoseSource::None) return std::nullopt;
  return world_T_moved ? *world_T_moved * start_T_predicted_ : start_ * start_T_predicted_;
}

}  // namespace relslam::eval
