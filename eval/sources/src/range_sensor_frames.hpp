#pragma once
// Internal to the sources layer: the planar simulation's range sensors (planar.sensor "laser"
// or "depth"). Each frame of the plane sensor gets the robot's noisy odometry and, with the
// laser, the scan taken at the same pose (PlaneFrame::scan, which scan-matching baselines read);
// recorded, the frames go to an MRPT rawlog (laser.rawlog, depth.rawlog) as MRPT's tools read
// it.

#include "relslam/core/plane_object.hpp"
#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/io/scan_rawlog.hpp"
#include "relslam/sim/depth_camera.hpp"
#include "relslam/sim/laser_sensor.hpp"
#include "relslam/sim/planar_world.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <memory>
#include <optional>

namespace relslam::eval {

class RangeSensorFrames {
 public:
  // Null unless the scenario's planar.sensor is laser or depth. InputError at planar.laser or
  // planar.depth when the sensor's options fail their check.
  static std::unique_ptr<RangeSensorFrames> make(const LoadedScenario& loaded, const sim::PlanarWorld& world);

  // laser.rawlog or depth.rawlog in dir, written as frames pass.
  void record_into(const std::filesystem::path& dir);
  // Frame k at world_T_robot (previous: frame k − 1's true pose, none at k = 0): its odometry
  // and scan into `frame`, and into the rawlog when recording.
  void add(int k, const PlanarPose& world_T_robot, const std::optional<PlanarPose>& previous, PlaneFrame& frame);
  void finish();
  nlohmann::json describe() const;

 private:
  RangeSensorFrames(const LoadedScenario& loaded, const sim::PlanarWorld& world);
  const sim::PlanarWorld& world_;
  const PlanarOptions& options_;
  std::uint64_t seed_;
  std::optional<sim::LaserSensor> laser_;
  std::optional<sim::DepthCamera> depth_;
  std::unique_ptr<ScanRawlogWriter> rawlog_;
  std::optional<PlanarPose> unrecorded_odometry_;  // depth: odometry summed over frames not recorded
  long long recorded_ = 0;
};

}  // namespace relslam::eval
