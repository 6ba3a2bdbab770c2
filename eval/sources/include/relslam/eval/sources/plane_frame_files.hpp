#pragma once
// The files a planar run's plane frames are written to and read back from: one writer (the
// planar simulation's recorder) and one reader (the plane file source) share their columns.

#include <string>
#include <vector>

namespace relslam::eval {

// plane_observations.csv: one row per observed plane, in the robot frame of its iteration (the
// planar half's frame: x right, z forward, heading about the vertical), with what the
// simulator knows of it (true_wall -1 and the *_true_end flags 1 where nothing is known) and
// its height range.
inline const std::vector<std::string> kPlaneObservationColumns = {
    "iteration", "index", "true_wall", "kp1_x", "kp1_z", "kp2_x", "kp2_z", "kp1_true_end", "kp2_true_end",
    "y_lo",      "y_hi"};

// ground_truth_poses.csv: the true planar pose of every iteration, world_T_robot as (x, z,
// heading in radians), exactly as the algorithm's scores use it (a TUM row's quaternion rounds
// the heading in its last bits).
inline const std::vector<std::string> kPlanarPoseColumns = {"iteration", "x", "z", "heading_rad"};

}  // namespace relslam::eval
