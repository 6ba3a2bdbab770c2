#pragma once
// Internal to the algorithms layer: the factory registry.cpp lists.

#include "relslam/core/planar_pose.hpp"
#include "relslam/eval/algorithms/plane_algorithm.hpp"
#include "relslam/plane/options.hpp"

#include <memory>

namespace relslam::eval {

std::unique_ptr<PlaneAlgorithm> make_relative_plane(const plane::RelativePlaneOptions& options,
                                                    const PlanarPose& world_T_start);

}  // namespace relslam::eval
