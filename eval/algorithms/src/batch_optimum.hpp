#pragma once
// Internal to the algorithms layer: the factory registry.cpp lists.

#include "relslam/eval/algorithms/algorithm.hpp"
#include "relslam/eval/config/batch_optimum_options.hpp"
#include "relslam/eval/config/ekf6d_options.hpp"
#include "relslam/eval/io/range_bearing.hpp"
#include "relslam/point/options.hpp"

#include <cstdint>
#include <memory>

namespace relslam::eval {

// `relative_point` configures the Relative Point run it starts from (start relative_point);
// `ekf` gives the EKF's models when noise_model or motion_model is ekf6d.
std::unique_ptr<Algorithm> make_batch_optimum(const BatchOptimumOptions& options, const Ekf6dOptions& ekf,
                                              const point::PointSlamOptions& relative_point,
                                              const RangeBearingSensor& sensor, std::uint64_t seed);

}  // namespace relslam::eval
