#pragma once
// Rawlogs of the simulated range sensors (sim/laser_sensor.hpp, sim/depth_camera.hpp) as MRPT's
// tools read them: action-first records (odometry since the previous frame, then a sensory
// frame holding one CObservation2DRangeScan or CObservation3DRangeScan), the form MRPT's
// icp-slam application maps. This header hides MRPT.

#include "relslam/core/laser_scan.hpp"
#include "relslam/core/planar_pose.hpp"
#include "relslam/sim/depth_camera.hpp"

#include <filesystem>
#include <memory>
#include <optional>

namespace relslam::eval {

class ScanRawlogWriter {
 public:
  // Creates the file (gzip when asked); std::runtime_error when it cannot.
  ScanRawlogWriter(const std::filesystem::path& path, bool gzip);
  ~ScanRawlogWriter();
  ScanRawlogWriter(const ScanRawlogWriter&) = delete;
  ScanRawlogWriter& operator=(const ScanRawlogWriter&) = delete;

  // One laser scan; `odometry` is the robot's motion since the previous record, in its robot
  // frame (none on the first); `range_sigma` the scanner's stated range error.
  void write(const LaserScan& scan, double range_sigma, const std::optional<PlanarPose>& odometry, double timestamp_s);
  // One depth image from `camera`, likewise.
  void write(const sim::DepthFrame& frame, const sim::DepthCameraOptions& camera,
             const std::optional<PlanarPose>& odometry, double timestamp_s);
  void close();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace relslam::eval
