#pragma once
// What an algorithm may see at one iteration. Part of relslam/core: Eigen only.

#include <Eigen/Core>
#include <vector>

namespace relslam {

// Robot frame, as in thesis Chapter 6: +x left, +y up, +z forward (right-handed, y vertical).
// The world frame is the robot frame at iteration 0, so maps and truth share one frame.

// One iteration's detections, untransformed: each point is in that iteration's robot frame.
// Truth (landmark ids, true pose) is deliberately absent; it travels in TruthFrame.
struct ObservationFrame {
  int iteration = 0;
  std::vector<Eigen::Vector3d> points;  // p_robot; order carries no meaning (the sensor shuffles)
};

}  // namespace relslam
