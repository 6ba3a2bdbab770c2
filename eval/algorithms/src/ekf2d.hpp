#pragma once
// Internal to the algorithms layer: the factory of MRPT's planar EKF-SLAM (keeps MRPT out of headers).

#include "relslam/eval/algorithms/algorithm.hpp"
#include "relslam/eval/config/ekf2d_options.hpp"
#include "relslam/eval/io/range_bearing.hpp"

#include <memory>

namespace relslam::eval {

// `use_odometry`: feed each frame's odometry as MRPT's 2D odometry action (algorithm ekf2d);
// otherwise empty actions, the constant-position model. `name`: as the scenario lists it.
std::unique_ptr<Algorithm> make_ekf2d(const Ekf2dOptions& options, const std::string& name, bool use_odometry,
                                      const RangeBearingSensor& sensor);

}  // namespace relslam::eval
