#pragma once
// The simulated planar world as a plane frame source (scenario kind "planar"): the scenario's
// map file with its planar.* settings applied, simulated frame by frame; given a run folder,
// the files of `relslam simulate` are written there as frames pass. With planar.sensor
// "points" each frame is the point sensor's, through the plane extractor (point_extraction.hpp).

#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/io/tum_writer.hpp"
#include "relslam/eval/sources/plane_frame_source.hpp"
#include "relslam/eval/sources/point_extraction.hpp"
#include "relslam/sim/planar_simulator.hpp"

#include <filesystem>
#include <memory>
#include <optional>

namespace relslam::eval {

class RangeSensorFrames;

// Where the scenario's planar.map points: an existing file (as given, or beside the scenario
// file), or a name in the scenario folder's maps/ or the repository's scenarios/maps/.
// InputError at planar.map, listing the known names, when there is none.
std::filesystem::path resolve_planar_map(const LoadedScenario& loaded);

// The scenario's map, read from `file` (resolve_planar_map), with its planar.* settings applied (loops, frustum, visibility, culling,
// noise). Throws InputError naming the map file or the key at fault, also when the robot would
// never see two walls at once (the algorithm would have nothing to relate, Rule 7).
sim::PlanarMap build_planar_map(const LoadedScenario& loaded, const std::filesystem::path& file);

// The map planar.generate draws (sim/map_generator.hpp), before the planar.* settings are
// applied: what generated_map.json holds. InputError at planar.generate.* when it cannot be drawn.
sim::PlanarMap generated_planar_map(const LoadedScenario& loaded);

// The name of the map file a run of a generated map writes into its folder.
inline constexpr const char* kGeneratedMapFile = "generated_map.json";

// output.point_frames as iterations of a run of `frames` iterations (negative ones count from
// the end). InputError at output.point_frames for an iteration outside the run, or when the
// run has no point sensor (`points` false).
std::vector<int> resolve_point_frames(const LoadedScenario& loaded, int frames, bool points);

// The field of view Relative Plane's relocalisation judges a place by (plane/field_of_view.hpp):
// the plane sensor's frustum, or the point sensor's (`points`, with its occlusion); none for
// walls seen otherwise than through the frustum.
std::optional<plane::FieldOfView> sensor_field_of_view(const sim::PlaneSensorOptions& sensor,
                                                       const sim::PointSensorOptions* points = nullptr);

// What the planar simulation produced (after stream()).
struct PlanarSimulationSummary {
  int iterations = 0;
  int walls = 0;
  long long observations = 0;  // planes reported over the run
  double visible_mean = 0;     // planes per iteration
  int visible_min = 0;
  int visible_max = 0;
  double distance_travelled = 0;
};

class PlanarSimulationSource final : public PlaneFrameSource {
 public:
  explicit PlanarSimulationSource(const LoadedScenario& loaded);
  ~PlanarSimulationSource() override;
  // Before stream(): write ground_truth_walls.csv now, and ground_truth_path.tum,
  // plane_observations.csv and (points) em_frames.csv as frames pass.
  void record_into(const std::filesystem::path& dir);

  std::string label() const override { return "run " + name_; }
  long long frames() const override { return frames_; }
  const std::vector<PlaneObject>& walls() const override { return walls_; }
  PlanarPose start() const override { return simulator_.path().world_T_robot(0); }
  void stream(const Consumer& consume) override;
  nlohmann::json describe() const override;
  // With the point sensor: t_extract_ms and extracted_planes. On a generated map, the truth of
  // what is in view (the walls the noise-free plane sensor reports): truth_walls_in_view and
  // truth_wall_angle_deg, the largest angle between two of them (0 to 90; over 20: two
  // non-parallel walls, which constrain the pose, thesis 4.2.5).
  std::vector<std::string> frame_columns() const override;
  // The map's frustum, with occlusion for the point, laser and depth sensors (the plane sensor
  // sees through walls, thesis Fig 100); none unless the walls are seen through the frustum.
  std::optional<plane::FieldOfView> field_of_view() const override;

  const sim::PlanarMap& map() const { return map_; }
  const sim::PlanarSimulator& simulator() const { return simulator_; }
  const PlanarSimulationSummary& summary() const { return summary_; }
  // Frame k as stream() gives it (the plane sensor's, or the points' extracted planes).
  sim::PlaneSimFrame frame(int k);
  // The point sensor's extraction (planar.sensor "points"), else null.
  const PointExtraction* extraction() const { return extraction_.get(); }

 private:
  struct Recorder;
  // The frame_columns() fields of the frame just extracted.
  std::vector<CsvField> measured() const;
  nlohmann::json describe_run() const;
  std::string name_;
  std::filesystem::path map_file_;
  std::optional<sim::PlanarMap> generated_;  // planar.generate's map as drawn
  sim::PlanarMap map_;
  sim::PlanarSimulator simulator_;
  int frames_ = 0;
  std::vector<PlaneObject> walls_;
  std::unique_ptr<PointExtraction> extraction_;
  std::unique_ptr<RangeSensorFrames> range_;  // planar.sensor laser or depth, else null
  std::vector<int> point_frames_;  // output.point_frames, resolved
  std::unique_ptr<Recorder> recorder_;
  PlanarSimulationSummary summary_;
  std::optional<sim::PlaneSensor> truth_sensor_;  // noise-free, on a generated map
  int truth_walls_ = 0;
  double truth_angle_deg_ = 0;
};

}  // namespace relslam::eval
