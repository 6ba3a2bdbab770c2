#include "range_sensor_frames.hpp"

#include "relslam/em/dense_extraction.hpp"
#include "relslam/em/em_random.hpp"
#include "relslam/em/plane_conversion.hpp"
#include "relslam/eval/sources/cloud_planes.hpp"
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
      extract_(options_.sensor == PlanarSensorKind::Laser ? options_.laser_planes == LaserPlanes::Extracted
                                                           : options_.depth_planes == LaserPlanes::Extracted) {
  if (options_.sensor == PlanarSensorKind::Laser) laser_.emplace(options_.laser);
  else depth_.emplace(options_.depth);
}

namespace {

// Evaluation only: the true wall ends in the robot frame, as em::extracted_plane_truth takes them.
std::vector<em::TrueWallEnds> true_ends(const sim::PlanarWorld& world, const PlanarPose& world_T_robot) {
  std::vector<em::TrueWallEnds> ends;
  for (const sim::Wall& w : world.walls)
    ends.push_back({w.id, world_T_robot.inverse_apply(w.a), world_T_robot.inverse_apply(w.b)});
  return ends;
}

// Evaluation only: an extracted wall's truth is the wall most of its rays hit, and an end is the
// wall's real end when one of that wall's true ends lies within `end_tolerance` of it, as for
// the planes found in the point sensor's points (em::extracted_plane_truth).
std::vector<PlaneTruth> wall_truth(const std::vector<scan::ExtractedWall>& walls, const sim::LaserSimFrame& shot,
                                   const sim::PlanarWorld& world, const PlanarPose& world_T_robot,
                                   double end_tolerance) {
  std::vector<int> ray_wall_ids(shot.wall.size(), -1);
  for (std::size_t i = 0; i < shot.wall.size(); ++i)
    if (shot.wall[i] >= 0) ray_wall_ids[i] = world.walls[static_cast<std::size_t>(shot.wall[i])].id;
  const std::vector<em::TrueWallEnds> ends = true_ends(world, world_T_robot);
  std::vector<PlaneTruth> out;
  for (const scan::ExtractedWall& w : walls)
    out.push_back(em::extracted_plane_truth(w.plane, w.rays, ray_wall_ids, ends, end_tolerance));
  return out;
}

// The depth camera's EM [C]: the extract command's defaults for metric depth frames (d_in 5 cm,
// 3σ of a Kinect at 3.5 m; a 4,800-point summary of the image), with d_in growing as the
// camera's 3σ beyond that (σ = noise_per_depth2 · z²; the range bounds the depth): a fixed 5 cm
// split the walls beyond 5 units, where σ reaches 4–9 cm, into pieces tilted up to 80° that
// Relative Plane took for walls of their own.
CloudPlaneOptions depth_extraction(const sim::DepthCameraOptions& camera) {
  CloudPlaneOptions o;
  o.em.inlier_per_range2 = 3.0 * camera.noise_per_depth2;
  return o;
}

// A real end is known to within two summary pixels at 2.5 units (stride 8 at 525 px) [C].
constexpr double kDepthEndTolerance = 0.1;

// Whether a wall's end (robot frame) lies where the depth camera stopped seeing rather than where
// the wall stops, as the plane sensor flags the ends its clip made (PlaneObject::a_cut, b_cut):
// within the summary's stride (8 pixels) of the image's side, or within 3σ of the depth (plus
// 5 cm) of the nearest or farthest return [C]. Ends hidden behind a nearer wall are not flagged.
// relative_plane.open_cut_ends and observed_anchor read the flags: a depth camera's first wall
// cut at both ends says nothing about where along it the start was.
bool depth_cut(const Eigen::Vector2d& end, const sim::DepthCameraOptions& camera) {
  constexpr double kSidePixels = 8;
  const double depth = end.x();
  if (depth <= camera.min_depth + 0.05) return true;
  const double column = camera.cx - camera.fx * end.y() / depth;  // image x runs to the robot's right (-z)
  const double sigma = camera.noise_per_depth2 * camera.max_depth * camera.max_depth;
  return column < kSidePixels || column > camera.width - 1 - kSidePixels ||
         depth >= camera.max_depth - 3.0 * sigma - 0.05;
}

}  // namespace

// The depth camera's walls in place of the plane sensor's planes. The image's points are in the
// planar robot frame with the camera at the origin (y from the camera), so the walls' heights are
// moved up by the camera's height to stand on the floor like the plane sensor's.
void RangeSensorFrames::extract(int k, const sim::DepthFrame& image, sim::PlaneSimFrame& frame) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Eigen::Vector3d> points = sim::depth_points(image, options_.depth);
  const em::DenseCloud cloud{points, image.width, image.height};
  const CloudPlaneOptions extraction = depth_extraction(options_.depth);
  const em::DenseResult found = em::extract_dense(cloud, em::EmVariant::Em2, extraction.em, extraction.dense,
                                                 em::em_frame_seed(seed_, k));
  em::ExtractedPlanes walls = em::to_plane_objects(found.result, extraction.em, k);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  for (PlaneObject& p : walls.frame.planes) {
    p.y_lo += options_.depth.camera_height;
    p.y_hi += options_.depth.camera_height;
    p.a_cut = depth_cut(p.a, options_.depth);
    p.b_cut = depth_cut(p.b, options_.depth);
  }
  frame.observation.planes = std::move(walls.frame.planes);
  const std::vector<em::TrueWallEnds> ends = true_ends(world_, frame.truth.world_T_robot);
  frame.truth.planes.clear();
  for (std::size_t i = 0; i < frame.observation.planes.size(); ++i)
    frame.truth.planes.push_back(em::extracted_plane_truth(frame.observation.planes[i], walls.support[i], image.truth,
                                                           ends, kDepthEndTolerance));
  count(ms, static_cast<int>(frame.observation.planes.size()));
}

void RangeSensorFrames::count(double ms, int walls) {
  last_ms_ = ms;
  last_walls_ = walls;
  ms_total_ += ms;
  walls_total_ += walls;
  ++frames_;
}

// The laser's walls in place of the plane sensor's planes.
void RangeSensorFrames::extract(int k, const sim::LaserSimFrame& shot, sim::PlaneSimFrame& frame) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<scan::ExtractedWall> walls = scan::extract_walls(shot.scan, walls_, k);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  frame.observation.planes.clear();
  for (const scan::ExtractedWall& w : walls) frame.observation.planes.push_back(w.plane);
  // A real end is known to within the extractor's corner distance [C].
  frame.truth.planes = wall_truth(walls, shot, world_, frame.truth.world_T_robot, walls_.corner_distance);
  count(ms, static_cast<int>(walls.size()));
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
  const bool record = rawlog_ && k % options_.depth_record_every == 0;
  if (!extract_ && !record) return;
  const sim::DepthFrame image = depth_->frame(world_, world_T_robot, seed_, k);
  if (extract_) extract(k, image, sim_frame);
  if (!record) return;
  rawlog_->write(image, options_.depth, unrecorded_odometry_, stamp);
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
  if (depth_) j["depth_planes"] = std::string(to_string(options_.depth_planes));
  if (extract_) {
    const double n = frames_ > 0 ? static_cast<double>(frames_) : 1.0;
    j[laser_ ? "walls_per_scan" : "walls_per_image"] = static_cast<double>(walls_total_) / n;
    j["extract_ms_mean"] = ms_total_ / n;
  }
  if (depth_) j["image"] = std::to_string(options_.depth.width) + "x" + std::to_string(options_.depth.height);
  return j;
}

}  // namespace relslam::eval
