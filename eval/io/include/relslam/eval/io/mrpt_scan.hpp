#pragma once
// Internal to relslam_eval: our planar laser scans, depth images and planar odometry as MRPT's
// CObservation2DRangeScan, CObservation3DRangeScan and CActionRobotMovement2D, the one
// conversion both the rawlog writer (scan_rawlog.hpp) and the ICP-SLAM baseline use
// (algorithms/ include it from here, as mrpt_observation.hpp). Axes: the planar half's x, z and
// heading are MRPT's x, y and yaw (laser_scan.hpp).

#include "relslam/core/laser_scan.hpp"
#include "relslam/core/planar_pose.hpp"
#include "relslam/sim/depth_camera.hpp"

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <memory>

namespace relslam::eval {

// MRPT's planar pose of ours and back.
mrpt::poses::CPose2D mrpt_pose_of(const PlanarPose& pose);
PlanarPose planar_pose_of(const mrpt::poses::CPose2D& pose);

// The scan as MRPT's 2-D range scan: its rays evenly spread over the aperture, right to left;
// a scan whose first ray is not at −aperture/2 has its centre turned into the sensor's yaw.
// stdError is `range_sigma` (what the scanner states, 0.01 m for SENA's).
std::shared_ptr<mrpt::obs::CObservation2DRangeScan> range_scan_observation(const LaserScan& scan, double timestamp_s,
                                                                           double range_sigma);

// A depth image as MRPT's Kinect-like 3-D range scan (range image in millimetres, range =
// depth), the camera `camera_height` above the robot's origin looking along its +x.
std::shared_ptr<mrpt::obs::CObservation3DRangeScan> depth_observation(const sim::DepthFrame& frame,
                                                                      const sim::DepthCameraOptions& camera,
                                                                      double timestamp_s);

// The robot's motion since the previous frame (in that frame's robot frame) as an odometry
// action with MRPT's default Gaussian motion model, stamped (MRPT's map builders require it);
// an empty collection without one.
mrpt::obs::CActionCollection planar_odometry_action(const std::optional<PlanarPose>& increment, double timestamp_s);

}  // namespace relslam::eval
