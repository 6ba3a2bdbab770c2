#pragma once
// Internal to the sources layer: the planar simulation's range sensors (planar.sensor "laser"
// or "depth"). Each frame of the plane sensor gets the robot's noisy odometry and, with the
// laser, the scan taken at the same pose (PlaneFrame::scan, which scan-matching baselines read)
// and, unless planar.laser_planes is "sensor", the walls extracted from that scan in place of
// the plane sensor's planes, with their truth (the wall most of its rays hit); with the depth
// camera, unless planar.depth_planes is "sensor", the walls EM2 finds in its image at sensor
// density (thesis 3.5, then 4.5's conversion), with their truth (the wall most of their pixels
// see). Recorded, the frames go to an MRPT rawlog (laser.rawlog, depth.rawlog) as MRPT's tools
// read it.

#include "relslam/core/plane_object.hpp"
#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/io/scan_rawlog.hpp"
#include "relslam/sim/depth_camera.hpp"
#include "relslam/sim/laser_sensor.hpp"
#include "relslam/sim/plane_sensor.hpp"
#include "relslam/sim/planar_world.hpp"
#include "relslam/eval/io/csv_writer.hpp"

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
  // Frame k at frame.truth.world_T_robot (previous: frame k − 1's true pose, none at k = 0): its
  // odometry and scan into `frame` (with the laser's extracted walls, its planes and their
  // truth), and into the rawlog when recording.
  void add(int k, const std::optional<PlanarPose>& previous, sim::PlaneSimFrame& frame);
  // Whether frames carry extracted walls: then the per-frame fields below.
  bool extracts() const { return extract_; }
  static std::vector<std::string> columns() { return {"t_extract_ms", "walls"}; }
  std::vector<CsvField> measured() const;
  void finish();
  nlohmann::json describe() const;

 private:
  RangeSensorFrames(const LoadedScenario& loaded, const sim::PlanarWorld& world);
  void extract(int k, const sim::LaserSimFrame& shot, sim::PlaneSimFrame& frame);
  void extract(int k, const sim::DepthFrame& image, sim::PlaneSimFrame& frame);
  void count(double ms, int walls);
  const sim::PlanarWorld& world_;
  PlanarOptions options_;  // a copy: the source may outlive the scenario it was built from
  std::uint64_t seed_;
  std::optional<sim::LaserSensor> laser_;
  scan::WallExtractionOptions walls_;
  bool extract_ = false;
  double last_ms_ = 0, ms_total_ = 0;
  int last_walls_ = 0;
  long long walls_total_ = 0, frames_ = 0;
  std::optional<sim::DepthCamera> depth_;
  std::unique_ptr<ScanRawlogWriter> rawlog_;
  std::optional<PlanarPose> unrecorded_odometry_;  // depth: odometry summed over frames not recorded
  long long recorded_ = 0;
};

}  // namespace relslam::eval
