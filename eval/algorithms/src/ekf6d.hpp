#pragma once
// Internal to the algorithms layer: the factory of MRPT's 6D EKF baseline (keeps MRPT out of headers).

#include "relslam/eval/algorithms/algorithm.hpp"
#include "relslam/eval/config/ekf6d_options.hpp"
#include "relslam/eval/io/range_bearing.hpp"

#include <memory>

namespace relslam::eval {

std::unique_ptr<Algorithm> make_ekf6d(const Ekf6dOptions& options, const RangeBearingSensor& sensor);

}  // namespace relslam::eval
