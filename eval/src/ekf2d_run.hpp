#pragma once
// Internal to relslam_eval: the factory of MRPT's planar EKF-SLAM runs (keeps MRPT out of headers).

#include "relslam/eval/algorithm_run.hpp"
#include "relslam/eval/ekf2d_options.hpp"
#include "relslam/eval/landmark_truth.hpp"
#include "relslam/eval/rawlog.hpp"

namespace relslam::eval {

// `use_odometry`: feed each frame's odometry as MRPT's 2D odometry action (algorithm ekf2d);
// otherwise empty actions, the constant-position model (ekf2d_no_odometry).
std::unique_ptr<AlgorithmRun> make_ekf2d_run(const Ekf2dOptions& options, bool use_odometry, const RangeBearingSensor& sensor,
                                             const LandmarkTruth& truth, const std::filesystem::path& dir);

}  // namespace relslam::eval
