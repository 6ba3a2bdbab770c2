#include "range_sensor_frames.hpp"

#include "relslam/em/plane_conversion.hpp"
#include "relslam/eval/io/rawlog.hpp"
#include "relslam/scan/wall_extraction.hpp"
#include "relslam/sim/odometry_noise.hpp"

#include <chrono>

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
    : world_(world),
      options_(loaded.scenario.planar),
      seed_(loaded.scenario.seed),
      walls_(loaded.scenario.laser.walls),
      extract_(options_.sensor == PlanarSensorKind::Laser && options_.laser_planes == LaserPlanes::Extracted) {
  if (options_.sensor == PlanarSensorKind::Laser) laser_.emplace(options_.laser);
  else depth_.emplace(options_.depth);
}

namespace {

// Evaluation only: an extracted wall's truth is the wall most of its rays hit, and an end is the
// wall's real end when one of that wall's true ends lies within `end_tolerance` of it, as for
// the planes found in the point sensor's points (em::extracted_plane_truth).
std::vector<PlaneTruth> wall_truth(const std::vector<scan::ExtractedWall>& walls, const sim::LaserSimFrame& shot,
                                   const sim::PlanarWorld& world, const PlanarPose& world_T_robot,
                                   double end_tolerance) {
  std::vector<int> ray_wall_ids(shot.wall.size(), -1);
  for (std::size_t i = 0; i < shot.wall.size(); ++i)
    if (shot.wall[i] >= 0) ray_wall_ids[i] = world.walls[static_cast<std::size_t>(shot.wall[i])].id;
  std::vector<em::TrueWallEnds> ends;
  for (const sim::Wall& w : world.walls)
    ends.push_back({w.id, world_T_robot.inverse_apply(w.a), world_T_robot.inverse_apply(w.b)});
  std::vector<PlaneTruth> out;
  for (const scan::ExtractedWall& w : walls)
    out.push_back(em::extracted_plane_truth(w.plane, w.rays, ray_wall_ids, ends, end_tolerance));
  return out;
}

}  // namespace

// The laser's walls in place of the plane sensor's planes.
void RangeSensorFrames::extract(int k, const sim::LaserSimFrame& shot, sim::PlaneSimFrame& frame) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<scan::ExtractedWall> walls = scan::extract_walls(shot.scan, walls_, k);
  last_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  frame.observation.planes.clear();
  for (const scan::ExtractedWall& w : walls) frame.observation.planes.push_back(w.plane);
  // A real end is known to within the extractor's corner distance [C].
  frame.truth.planes = wall_truth(walls, shot, world_, frame.truth.world_T_robot, walls_.corner_distance);
  last_walls_ = static_cast<int>(walls.size());
  ms_total_ += last_ms_;
  walls_total_ += last_walls_;
  ++frames_;
}

std::vector<CsvField> RangeSensorFrames::measured() const {
  return {CsvField(last_ms_), CsvField(static_cast<long long>(last_walls_))};
}

void RangeSensorFrames::record_into(const std::filesystem::path& dir) {
  rawlog_ = std::make_unique<ScanRawlogWriter>(dir / (laser_ ? "laser.rawlog" : "depth.rawlog"), false);
}

void RangeSensorFrames::add(int k, const std::optional<PlanarPose>& previous, sim::PlaneSimFrame& sim_frame) {
  const PlanarPose& world_T_robot = sim_frame.truth.world_T_robot;
  PlaneFrame& frame = sim_frame.observation;
  if (previous) frame.odometry = sim::noisy_odometry(previous->inverse() * world_T_robot, options_.odometry, seed_, k);
  const double stamp = kSimulationEpoch_s + k;
  if (laser_) {
    sim::LaserSimFrame shot = laser_->scan(world_, world_T_robot, seed_, k);
    shot.scan.stamp_s = stamp;
    if (extract_) extract(k, shot, sim_frame);
    auto scan = std::make_shared<LaserScan>(std::move(shot.scan));
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
  if (laser_) j["laser_planes"] = std::string(to_string(options_.laser_planes));
  if (extract_) {
    const double n = frames_ > 0 ? static_cast<double>(frames_) : 1.0;
    j["walls_per_scan"] = static_cast<double>(walls_total_) / n;
    j["extract_ms_mean"] = ms_total_ / n;
  }
  if (depth_) j["image"] = std::to_string(options_.depth.width) + "x" + std::to_string(options_.depth.height);
  return j;
}

}  // namespace relslam::eval
