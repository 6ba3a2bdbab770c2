#pragma once
// Internal to the algorithms layer: the factory registry.cpp lists.

#include "relslam/eval/algorithms/algorithm.hpp"
#include "relslam/point/options.hpp"

#include <memory>

namespace relslam::eval {

std::unique_ptr<Algorithm> make_relative_point(const point::PointSlamOptions& options);

}  // namespace relslam::eval
