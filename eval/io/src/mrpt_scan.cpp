#include "relslam/eval/io/mrpt_scan.hpp"

#include <mrpt/core/Clock.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>

namespace relslam::eval {

mrpt::poses::CPose2D mrpt_pose_of(const PlanarPose& pose) {
  return {pose.translation.x(), pose.translation.y(), pose.heading};
}

PlanarPose planar_pose_of(const mrpt::poses::CPose2D& pose) { return PlanarPose::from(pose.x(), pose.y(), pose.phi()); }

std::shared_ptr<mrpt::obs::CObservation2DRangeScan> range_scan_observation(const LaserScan& scan, double timestamp_s,
                                                                           double range_sigma) {
  auto obs = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
  const std::size_t n = scan.size();
  obs->resizeScan(n);
  for (std::size_t i = 0; i < n; ++i) {
    obs->setScanRange(i, scan.ranges[i]);
    obs->setScanRangeValidity(i, scan.valid[i] != 0);
  }
  const double aperture = n > 1 ? static_cast<double>(n - 1) * scan.bearing_step_rad : 0.0;
  obs->aperture = static_cast<float>(aperture);
  obs->rightToLeft = true;
  obs->maxRange = static_cast<float>(scan.max_range);
  obs->stdError = static_cast<float>(range_sigma);
  const double centre = scan.start_bearing_rad + 0.5 * aperture;  // 0 for a symmetric scan
  obs->sensorPose = mrpt::poses::CPose3D(scan.robot_T_sensor.translation.x(), scan.robot_T_sensor.translation.y(), 0.0,
                                         scan.robot_T_sensor.heading + centre, 0.0, 0.0);
  obs->timestamp = mrpt::Clock::fromDouble(timestamp_s);
  obs->sensorLabel = "LASER";
  return obs;
}

std::shared_ptr<mrpt::obs::CObservation3DRangeScan> depth_observation(const sim::DepthFrame& frame,
                                                                      const sim::DepthCameraOptions& camera,
                                                                      double timestamp_s) {
  auto obs = std::make_shared<mrpt::obs::CObservation3DRangeScan>();
  obs->hasRangeImage = true;
  obs->range_is_depth = true;
  obs->rangeUnits = 0.001f;
  obs->rangeImage_setSize(frame.height, frame.width);
  for (int v = 0; v < frame.height; ++v)
    for (int u = 0; u < frame.width; ++u) {
      const double mm = std::round(static_cast<double>(frame.at(u, v)) / obs->rangeUnits);
      obs->rangeImage(v, u) = static_cast<std::uint16_t>(std::clamp(mm, 0.0, 65535.0));
    }
  obs->cameraParams.ncols = static_cast<std::uint32_t>(frame.width);
  obs->cameraParams.nrows = static_cast<std::uint32_t>(frame.height);
  obs->cameraParams.setIntrinsicParamsFromValues(camera.fx, camera.fy, camera.cx, camera.cy);
  obs->cameraParamsIntensity = obs->cameraParams;
  obs->maxRange = static_cast<float>(camera.max_depth);
  obs->sensorPose = mrpt::poses::CPose3D(0.0, 0.0, camera.camera_height, 0.0, 0.0, 0.0);
  obs->timestamp = mrpt::Clock::fromDouble(timestamp_s);
  obs->sensorLabel = "DEPTH";
  return obs;
}

mrpt::obs::CActionCollection planar_odometry_action(const std::optional<PlanarPose>& increment, double timestamp_s) {
  mrpt::obs::CActionCollection actions;
  if (!increment) return actions;
  mrpt::obs::CActionRobotMovement2D move;
  move.timestamp = mrpt::Clock::fromDouble(timestamp_s);
  move.computeFromOdometry(mrpt_pose_of(*increment), mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
  actions.insert(move);
  return actions;
}

}  // namespace relslam::eval
