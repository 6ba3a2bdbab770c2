#pragma once
// What an algorithm may see at one iteration. Part of relslam/core: Eigen only.

#include "relslam/core/rigid.hpp"

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace relslam {

// Robot frame, as in thesis Chapter 6: +x left, +y up, +z forward (right-handed, y vertical).
// The world frame is the robot frame at iteration 0, so maps and truth share one frame.

// One iteration's detections, untransformed: each point is in that iteration's robot frame.
// Truth (landmark ids, true pose) is deliberately absent; it travels in TruthFrame.
struct ObservationFrame {
  int iteration = 0;
  std::vector<Eigen::Vector3d> points;  // p_robot; order carries no meaning (the sensor shuffles)
  // The motion since the previous frame, previous_T_current, as the robot's own motion sensors
  // (wheel odometry) measured it, when it has any. The thesis's algorithms map without it; the
  // EKF baselines use it, and Relative Point may bridge frames it cannot register with it.
  std::optional<Rigid3> odometry;
  // When the frame was observed, seconds on the recording's clock (a rawlog's timestamps), so
  // trajectories line up with the recording's own ground truth; none for simulated frames,
  // whose time is their iteration. Algorithms map without it.
  std::optional<double> time_s;
};

}  // namespace relslam
