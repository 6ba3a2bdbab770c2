#pragma once
// One iteration's 3-D points on the planar world's walls, as a point sensor reports them: the
// input of EM plane extraction (thesis 3.5, Chapter 5; thesis 5.1, 3.5.1).
// Part of relslam/core: Eigen only. Truth travels separately, in PlanarPointTruthFrame, which
// only the evaluation reads.

#include "relslam/core/planar_pose.hpp"

#include <Eigen/Core>

#include <vector>

namespace relslam {

// Points in the planar world's robot frame at their iteration: the robot at the origin looking
// along +x, z lateral, y up (not the point world's frame of observation.hpp).
// Order carries no meaning (the sensor shuffles; thesis 3.5.4: the order of the incoming
// points can differ every run).
struct PlanarPointFrame {
  int iteration = 0;
  std::vector<Eigen::Vector3d> points;  // p_robot = (x, y, z)
};

// What the simulator knows of each point, for scoring only.
struct PlanarPointTruthFrame {
  int iteration = 0;
  PlanarPose world_T_robot;
  std::vector<int> wall_ids;  // wall_ids[i]: the true wall of PlanarPointFrame::points[i]
};

}  // namespace relslam
