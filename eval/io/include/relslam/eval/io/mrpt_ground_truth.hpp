#pragma once
// Ground truth in the text formats of MRPT's simul-landmarks and kf-slam: a robot path with one
// "x y z yaw pitch roll" row per step, and landmarks "x y z ..." with the id in column 7 (or
// the row number when there are only three columns). '%' and '#' start comments.

#include "relslam/core/rigid.hpp"

#include <filesystem>
#include <vector>

namespace relslam::eval {

struct TruthLandmark {
  int id = 0;
  Eigen::Vector3d p_world = Eigen::Vector3d::Zero();  // MRPT's world frame
};

// world_T_robot per row, MRPT's frames (x forward, y left, z up). Throws InputError with the
// file and line of a malformed row.
std::vector<Rigid3> read_mrpt_path(const std::filesystem::path& file);
std::vector<TruthLandmark> read_mrpt_landmarks(const std::filesystem::path& file);

}  // namespace relslam::eval
