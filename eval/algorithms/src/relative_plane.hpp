#pragma once
// Internal to the algorithms layer: the factory registry.cpp lists.

#include "relslam/core/planar_pose.hpp"
#include "relslam/eval/algorithms/plane_algorithm.hpp"
#include "relslam/eval/config/laser_options.hpp"
#include "relslam/plane/options.hpp"

#include <memory>

namespace relslam::eval {

// With `prediction` enabled, each frame is matched at its predicted pose (pose_prediction.hpp).
std::unique_ptr<PlaneAlgorithm> make_relative_plane(const plane::RelativePlaneOptions& options,
                                                    const MotionPredictionOptions& prediction,
                                                    const PlanarPose& world_T_start);

}  // namespace relslam::eval
