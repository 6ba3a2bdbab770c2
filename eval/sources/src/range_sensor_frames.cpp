#include "range_sensor_frames.hpp"

#include "relslam/eval/io/rawlog.hpp"
#include "relslam/sim/odometry_noise.hpp"

namespace relslam::eval {

std::unique_ptr<RangeSensorFrames> RangeSensorFrames::make(const LoadedScenario& loaded,
                                                           const sim::PlanarWorld& world) {
  const PlanarSensorKind kind = loaded.scenario.planar.sensor;
  if (kind != PlanarSensorKind::Laser && kind != PlanarSensorKind::Depth) return nullptr;
  try {
    return std::unique_ptr<RangeSensorFrames>(new RangeSensorFrames(loaded, world));
  } catch (const OptionError& e) {
    throw loaded.error(std::string("planar.") + std::string(to_string(kind)) + "." + e.field(), e.problem());
  }
}

RangeSensorFrames::RangeSensorFrames(const LoadedScenario& loaded, const sim::PlanarWorld& world)
    : world_(world), options_(loaded.scenario.planar), seed_(loaded.scenario.seed) {
  if (options_.sensor == PlanarSensorKind::Laser) laser_.emplace(options_.laser);
  else depth_.emplace(options_.depth);
}

void RangeSensorFrames::record_into(const std::filesystem::path& dir) {
  rawlog_ = std::make_unique<ScanRawlogWriter>(dir / (laser_ ? "laser.rawlog" : "depth.rawlog"), false);
}

void RangeSensorFrames::add(int k, const PlanarPose& world_T_robot, const std::optional<PlanarPose>& previous,
                            PlaneFrame& frame) {
  if (previous) frame.odometry = sim::noisy_odometry(previous->inverse() * world_T_robot, options_.odometry, seed_, k);
  const double stamp = kSimulationEpoch_s + k;
  if (laser_) {
    auto scan = std::make_shared<LaserScan>(laser_->scan(world_, world_T_robot, seed_, k).scan);
    scan->stamp_s = stamp;
    frame.scan = scan;
    if (rawlog_) rawlog_->write(*scan, options_.laser.range_sigma, frame.odometry, stamp), ++recorded_;
    return;
  }
  // Depth: the odometry of the frames between two recorded ones adds up into the next record's.
  if (frame.odometry) unrecorded_odometry_ = unrecorded_odometry_ ? *unrecorded_odometry_ * *frame.odometry : *frame.odometry;
  if (!rawlog_ || k % options_.depth_record_every != 0) return;
  rawlog_->write(depth_->frame(world_, world_T_robot, seed_, k), options_.depth, unrecorded_odometry_, stamp);
  unrecorded_odometry_.reset();
  ++recorded_;
}

void RangeSensorFrames::finish() {
  if (rawlog_) rawlog_->close();
}

nlohmann::json RangeSensorFrames::describe() const {
  nlohmann::json j = {{"sensor", std::string(to_string(options_.sensor))}, {"rawlog_records", recorded_}};
  if (laser_) j["rays"] = options_.laser.rays;
  if (depth_) j["image"] = std::to_string(options_.depth.width) + "x" + std::to_string(options_.depth.height);
  return j;
}

}  // namespace relslam::eval
