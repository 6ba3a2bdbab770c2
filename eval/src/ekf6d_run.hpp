#pragma once
// Internal to relslam_eval: the factory of the EKF baseline's run (keeps MRPT out of headers).

#include "relslam/eval/algorithm_run.hpp"
#include "relslam/eval/ekf6d_options.hpp"
#include "relslam/eval/landmark_truth.hpp"
#include "relslam/eval/rawlog.hpp"

namespace relslam::eval {

std::unique_ptr<AlgorithmRun> make_ekf6d_run(const Ekf6dOptions& options, const RangeBearingSensor& sensor,
                                             const LandmarkTruth& truth, const std::filesystem::path& dir);

}  // namespace relslam::eval
