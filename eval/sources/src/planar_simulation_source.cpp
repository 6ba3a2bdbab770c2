#include "relslam/eval/sources/planar_simulation_source.hpp"

#include "relslam/eval/config/scenario_half.hpp"
#include "relslam/eval/io/planar_map_file.hpp"
#include "relslam/eval/sources/plane_frame_files.hpp"
#include "relslam/sim/planar_sight.hpp"

#include "range_sensor_frames.hpp"

#include <algorithm>
#include <fstream>
#include <numbers>
#include <tuple>
#include <limits>

namespace relslam::eval {
namespace fs = std::filesystem;

namespace {

// The repository's maps: a name works from any working directory.
const fs::path kRepositoryMaps = fs::path(RELSLAM_SOURCE_DIR) / "scenarios" / "maps";

bool is_file(const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

std::string known_map_names(const std::vector<fs::path>& folders) {
  std::vector<std::string> names;
  for (const fs::path& folder : folders) {
    std::error_code ec;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder, ec))
      if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  return list.empty() ? "none found" : list;
}

}  // namespace

fs::path resolve_planar_map(const LoadedScenario& loaded) {
  const std::string& map = loaded.scenario.planar.map;
  const fs::path beside = loaded.file.empty() ? fs::path() : fs::path(loaded.file).parent_path();
  const std::vector<fs::path> candidates = {map, beside / map, beside / "maps" / (map + ".json"),
                                            kRepositoryMaps / (map + ".json")};
  for (const fs::path& candidate : candidates)
    if (is_file(candidate)) return candidate;
  throw loaded.error("planar.map", "no map file \"" + map + "\" and no map of that name (known: " +
                                       known_map_names({beside / "maps", kRepositoryMaps}) + ")");
}

namespace {

// The scenario's planar.* settings applied to `map` (read from a file or generated), checked
// that the robot sees two walls at once; `where` names the map in messages.
sim::PlanarMap with_planar_settings(const LoadedScenario& loaded, sim::PlanarMap map, const std::string& where,
                                    const std::string& key) {
  const PlanarOptions& o = loaded.scenario.planar;

  if (o.loops > 0) map.path.loops = o.loops;
  map.path.speed *= o.speed_scale;
  map.path.turn_rate_rad *= o.speed_scale;
  sim::PlaneSensorOptions& sensor = map.sensor;
  // The names were checked when the scenario was loaded (planar_options.cpp).
  if (o.frustum != kFromMap) {
    const sim::FrustumShape shape = sensor.frustum.shape;
    sensor.frustum = *sim::frustum_preset(o.frustum);
    sensor.frustum.shape = shape;
  }
  if (o.frustum_shape != kFromMap) sensor.frustum.shape = *sim::parse_frustum_shape(o.frustum_shape);
  if (o.visibility != kFromMap) sensor.mode = *sim::parse_plane_visibility(o.visibility);
  sensor.backface_cull = o.backface_cull;
  const sim::PlaneNoiseModel model =
      o.noise.model == kFromMap ? sensor.noise.model : *sim::parse_plane_noise_model(o.noise.model);
  const bool silent = o.noise.position_sigma == 0 && o.noise.rotation_sigma_rad == 0 && o.noise.end_sigma == 0;
  sensor.noise = model == sim::PlaneNoiseModel::None || silent
                     ? sim::PlaneNoiseOptions::none()
                     : sim::PlaneNoiseOptions{model, o.noise.position_sigma, o.noise.rotation_sigma_rad,
                                              o.noise.end_sigma};

  try {
    if (!sim::first_iteration_seeing(map, 2))
      throw loaded.error(key, where + " with the scenario's planar settings: the robot never sees two walls at once "
                                      "along its path, so the algorithm has nothing to relate (thesis Rule 7)");
  } catch (const OptionError& e) {
    throw loaded.error(key, where + " with the scenario's planar settings: " + e.field() + ": " + e.problem());
  }
  return map;
}

// Asked of half_of (scenario_half.hpp), the one place a kind picks its half.
void require_planar(const LoadedScenario& loaded) {
  if (!feeds_planes(loaded.scenario.kind))
    throw loaded.error("kind", "this scenario is not a planar world (kind \"planar\")");
}

}  // namespace

sim::PlanarMap build_planar_map(const LoadedScenario& loaded, const fs::path& file) {
  require_planar(loaded);
  return with_planar_settings(loaded, read_planar_map(file), file.string(), "planar.map");
}

sim::PlanarMap generated_planar_map(const LoadedScenario& loaded) {
  require_planar(loaded);
  const PlanarGenerateSettings& g = loaded.scenario.planar.generate;
  try {
    return sim::generate_map({g.family, g.seed, g.clearance});
  } catch (const OptionError& e) {
    throw loaded.error("planar.generate." + e.field(), e.problem());
  }
}

namespace {

bool generated(const LoadedScenario& loaded) { return loaded.scenario.planar.generate.family != sim::MapFamily::None; }

// The truth of what is in view: the walls the noise-free sensor reports, and the largest angle
// between two of them, degrees in [0, 90].
std::pair<int, double> walls_in_view(const sim::PlaneSimFrame& noise_free, const sim::PlanarWorld& world) {
  std::vector<Eigen::Vector2d> normals;
  for (const PlaneTruth& t : noise_free.truth.planes)
    for (const sim::Wall& w : world.walls)
      if (w.id == t.wall_id) normals.push_back(w.normal());
  double largest = 0;
  for (std::size_t i = 0; i < normals.size(); ++i)
    for (std::size_t j = i + 1; j < normals.size(); ++j)
      largest = std::max(largest, std::acos(std::min(1.0, std::abs(normals[i].dot(normals[j])))));
  return {static_cast<int>(normals.size()), largest * 180.0 / std::numbers::pi};
}

// The simulator with the point sensor when the scenario asks for points.
sim::PlanarSimulator planar_simulator(const LoadedScenario& loaded, const sim::PlanarMap& map) {
  if (loaded.scenario.planar.sensor != PlanarSensorKind::Points) return sim::PlanarSimulator(map, loaded.scenario.seed);
  try {
    return sim::PlanarSimulator(map, loaded.scenario.seed, point_sensor_options(loaded, map.sensor));
  } catch (const OptionError& e) {
    throw loaded.error("planar.sensor", "the point sensor: " + e.field() + ": " + e.problem());
  }
}

}  // namespace

std::vector<int> resolve_point_frames(const LoadedScenario& loaded, int frames, bool points) {
  const std::vector<int>& wanted = loaded.scenario.output.point_frames;
  if (!wanted.empty() && !points)
    throw loaded.error("output.point_frames", "needs the point sensor (planar.sensor \"points\")");
  std::vector<int> out;
  for (int k : wanted) {
    const int iteration = k < 0 ? frames + k : k;
    if (iteration < 0 || iteration >= frames)
      throw loaded.error("output.point_frames", "iteration " + std::to_string(k) + " is outside the run's " +
                                                    std::to_string(frames) + " iterations (0 to " +
                                                    std::to_string(frames - 1) + ", or -1 to -" +
                                                    std::to_string(frames) + " from the end)");
    out.push_back(iteration);
  }
  return out;
}

struct PlanarSimulationSource::Recorder {
  explicit Recorder(const fs::path& dir)
      : path(dir / "ground_truth_path.tum"),
        poses(dir / "ground_truth_poses.csv", kPlanarPoseColumns),
        observations(dir / "plane_observations.csv", kPlaneObservationColumns) {}
  TumWriter path;
  CsvWriter poses;  // the planar pose itself: exact, where a TUM row's quaternion rounds the heading
  CsvWriter observations;
};

PlanarSimulationSource::PlanarSimulationSource(const LoadedScenario& loaded)
    : name_(loaded.scenario.name),
      map_file_(generated(loaded) ? fs::path() : resolve_planar_map(loaded)),
      generated_(generated(loaded) ? std::optional<sim::PlanarMap>(generated_planar_map(loaded)) : std::nullopt),
      map_(generated_ ? with_planar_settings(loaded, *generated_, "the generated map \"" + generated_->name + "\"",
                                             "planar.generate.family")
                      : build_planar_map(loaded, map_file_)),
      simulator_(planar_simulator(loaded, map_)) {
  if (generated_) {
    sim::PlaneSensorOptions noise_free = map_.sensor;
    noise_free.noise = sim::PlaneNoiseOptions::none();
    truth_sensor_.emplace(noise_free, loaded.scenario.seed);
  }
  const int limit = loaded.scenario.planar.iterations;
  frames_ = limit > 0 ? std::min(limit, simulator_.iterations()) : simulator_.iterations();
  int max_id = -1;
  for (const sim::Wall& w : map_.world.walls) max_id = std::max(max_id, w.id);
  walls_.assign(static_cast<std::size_t>(max_id + 1), PlaneObject{});
  for (const sim::Wall& w : map_.world.walls) walls_[static_cast<std::size_t>(w.id)] = {w.a, w.b, 0.0, w.height, 0};
  if (simulator_.has_point_sensor())
    extraction_ = std::make_unique<PointExtraction>(loaded, walls_, simulator_.point_sensor().options());
  point_frames_ = resolve_point_frames(loaded, frames_, extraction_ != nullptr);
  range_ = RangeSensorFrames::make(loaded, map_.world);
}

PlanarSimulationSource::~PlanarSimulationSource() = default;

void PlanarSimulationSource::record_into(const fs::path& dir) {
  CsvWriter walls(dir / "ground_truth_walls.csv",
                  {"id", "a_x", "a_z", "b_x", "b_z", "length", "height", "normal_x", "normal_z", "one_sided"});
  for (const sim::Wall& w : map_.world.walls)
    walls.row(w.id, w.a.x(), w.a.y(), w.b.x(), w.b.y(), w.length(), w.height, w.normal().x(), w.normal().y(),
              w.one_sided);
  walls.close();
  if (generated_) {
    std::ofstream out(dir / kGeneratedMapFile);
    out << planar_map_text(*generated_);
    if (!out) throw std::runtime_error((dir / kGeneratedMapFile).string() + ": write failed");
  }
  recorder_ = std::make_unique<Recorder>(dir);
  if (extraction_) extraction_->record_into(dir, point_frames_);
  if (range_) range_->record_into(dir);
}

sim::PlaneSimFrame PlanarSimulationSource::frame(int k) {
  return extraction_ ? extraction_->extract(simulator_.point_frame(k)) : simulator_.frame(k);
}

void PlanarSimulationSource::stream(const Consumer& consume) {
  summary_ = {};
  summary_.iterations = frames_;
  summary_.walls = static_cast<int>(map_.world.walls.size());
  summary_.visible_min = frames_ > 0 ? std::numeric_limits<int>::max() : 0;
  for (int k = 0; k < frames_; ++k) {
    sim::PlaneSimFrame frame = this->frame(k);
    if (range_)
      range_->add(k, k > 0 ? std::optional<PlanarPose>(simulator_.path().world_T_robot(k - 1)) : std::nullopt, frame);
    const int seen = static_cast<int>(frame.observation.planes.size());
    summary_.observations += seen;
    summary_.visible_min = std::min(summary_.visible_min, seen);
    summary_.visible_max = std::max(summary_.visible_max, seen);
    if (k > 0)
      summary_.distance_travelled +=
          (frame.truth.world_T_robot.translation - simulator_.path().world_T_robot(k - 1).translation).norm();
    if (recorder_) {
      const PlanarPose& pose = frame.truth.world_T_robot;
      recorder_->path.write(k, rigid_from_planar(pose));
      recorder_->poses.row(k, pose.translation.x(), pose.translation.y(), pose.heading);
      for (int i = 0; i < seen; ++i) {
        const PlaneObject& p = frame.observation.planes[static_cast<std::size_t>(i)];
        const PlaneTruth& t = frame.truth.planes[static_cast<std::size_t>(i)];
        recorder_->observations.row(k, i, t.wall_id, p.a.x(), p.a.y(), p.b.x(), p.b.y(), t.a_is_wall_end,
                                    t.b_is_wall_end, p.y_lo, p.y_hi);
      }
    }
    if (truth_sensor_)
      std::tie(truth_walls_, truth_angle_deg_) =
          walls_in_view(truth_sensor_->observe(map_.world, frame.truth.world_T_robot, k), map_.world);
    consume(frame.observation, frame.truth, measured());
  }
  summary_.visible_mean = frames_ > 0 ? static_cast<double>(summary_.observations) / frames_ : 0.0;
  if (recorder_) {
    recorder_->path.close();
    recorder_->poses.close();
    recorder_->observations.close();
  }
  if (extraction_) extraction_->finish();
  if (range_) range_->finish();
}

nlohmann::json PlanarSimulationSource::describe() const {
  nlohmann::json d = describe_run();
  if (generated_) d["planar_simulation"]["generated_map"] = kGeneratedMapFile;
  return d;
}

nlohmann::json PlanarSimulationSource::describe_run() const {
  nlohmann::json out = {{"planar_simulation",
           {{"map", map_.name},
            {"map_file", map_file_.string()},
            {"iterations", summary_.iterations},
            {"walls", summary_.walls},
            {"observations", summary_.observations},
            {"visible_mean", summary_.visible_mean},
            {"distance_travelled", summary_.distance_travelled},
            {"sensor", std::string(to_string(extraction_ ? PlanarSensorKind::Points : PlanarSensorKind::Planes))},
            {"extraction", extraction_ ? extraction_->describe() : nlohmann::json()}}}};
  if (range_) out["planar_simulation"]["range_sensor"] = range_->describe();
  return out;
}

std::optional<plane::FieldOfView> sensor_field_of_view(const sim::PlaneSensorOptions& sensor,
                                                       const sim::PointSensorOptions* points) {
  // Walls seen otherwise than through the frustum (Maps A and B) have none.
  if (sensor.mode != sim::PlaneVisibility::Frustum) return std::nullopt;
  const sim::ViewingFrustum& f = points ? points->frustum : sensor.frustum;
  return plane::FieldOfView{.known = true,
                            .half_angle_rad = f.half_angle_rad,
                            .near = f.near,
                            .far = f.far,
                            .radial = f.shape == sim::FrustumShape::Radial,
                            .occlusion = points && points->occlusion,
                            .front_face_only = points ? points->backface_cull : sensor.backface_cull};
}

std::optional<plane::FieldOfView> PlanarSimulationSource::field_of_view() const {
  // A laser's or depth camera's own field of view is not the frustum's.
  if (range_) return std::nullopt;
  return sensor_field_of_view(map_.sensor, extraction_ ? &simulator_.point_sensor().options() : nullptr);
}

std::vector<std::string> PlanarSimulationSource::frame_columns() const {
  std::vector<std::string> columns;
  if (extraction_) columns = {"t_extract_ms", "extracted_planes"};
  if (range_ && range_->extracts()) columns = RangeSensorFrames::columns();
  if (truth_sensor_) columns.insert(columns.end(), {"truth_walls_in_view", "truth_wall_angle_deg"});
  return columns;
}

std::vector<CsvField> PlanarSimulationSource::measured() const {
  std::vector<CsvField> out;
  if (extraction_) {
    out.emplace_back(extraction_->last_ms());
    out.emplace_back(static_cast<long long>(extraction_->last_score().planes));
  }
  if (range_ && range_->extracts()) out = range_->measured();
  if (truth_sensor_) {
    out.emplace_back(static_cast<long long>(truth_walls_));
    out.emplace_back(truth_angle_deg_);
  }
  return out;
}

}  // namespace relslam::eval
