#pragma once
// Internal to the algorithms layer: the factories registry.cpp lists for the scan-matching
// baseline of the planar half and its dead-reckoning row.

#include "relslam/core/planar_pose.hpp"
#include "relslam/eval/algorithms/plane_algorithm.hpp"
#include "relslam/eval/config/icp_slam_options.hpp"
#include "relslam/eval/config/laser_options.hpp"

#include <memory>
#include <string>

namespace relslam::eval {

// MRPT's ICP-SLAM (CMetricMapBuilderICP, the engine of MRPT's icp-slam application) on each
// frame's laser scan, configured as icp-slam reads its .ini. Its pose is MRPT's estimate of
// the robot put at world_T_start; it keeps no planes (map() is empty), and its point map goes to
// icp_points.csv at the end of the run.
std::unique_ptr<PlaneAlgorithm> make_icp_slam(const IcpSlamOptions& options, const PlanarPose& world_T_start);

// The ini text CMetricMapBuilderICP is configured from: sections [ICP] and [MappingApplication]
// as in MRPT's icp-slam_demo_classic.ini, with the options' values.
std::string icp_slam_ini(const IcpSlamOptions& options);

// Dead reckoning: world_T_start followed by every frame's odometry. Throws (ending its run as
// failed) on a frame after the first without odometry.
std::unique_ptr<PlaneAlgorithm> make_odometry(const PlanarPose& world_T_start);

// Relative Plane's motion prediction alone (motion_prediction.*, with register_walls on):
// world_T_start followed by every frame's step, the odometry, the last step or none, refined
// by registering the frame's walls against the previous frame's. What Relative Plane is handed
// before it matches, as a path of its own; no planes.
std::unique_ptr<PlaneAlgorithm> make_wall_odometry(const MotionPredictionOptions& options,
                                                   const PlanarPose& world_T_start);

}  // namespace relslam::eval
