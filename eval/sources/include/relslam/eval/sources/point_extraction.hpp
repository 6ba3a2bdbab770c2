#pragma once
// The point sensor's frames turned into plane frames (planar.sensor "points"):
// each frame's points through the scenario's extractor (relative_plane.extractor, timed), the
// truth of every extracted plane (its points' majority wall, which ends are real; thesis 5.1
// step 5), and the extraction's score (metrics/extraction_score.hpp), one em_frames.csv row
// per frame when recording.

#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/metrics/extraction_score.hpp"
#include "relslam/eval/sources/plane_extractor.hpp"
#include "relslam/sim/plane_sensor.hpp"
#include "relslam/sim/point_sensor.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

namespace relslam::eval {

// The point sensor of a planar scenario: the map's frustum and back-face culling
// (PointSensorOptions::matching) with σ_pt = planar.noise.point_sigma.
sim::PointSensorOptions point_sensor_options(const LoadedScenario& loaded, const sim::PlaneSensorOptions& map_sensor);

class PointExtraction {
 public:
  // em_frames.csv's columns.
  static const std::vector<std::string>& columns();

  // walls: the true walls by id (world frame); `sensor`: the point sensor's options (spacing
  // and σ_pt set the end tolerance). InputError at relative_plane.extractor when this build
  // lacks the extractor.
  PointExtraction(const LoadedScenario& loaded, const std::vector<PlaneObject>& walls,
                  const sim::PointSensorOptions& sensor);
  // Before the first frame: write em_frames.csv into dir as frames pass, and the points of the
  // frames whose iterations are in point_frames to point_frames.csv (output.point_frames).
  void record_into(const std::filesystem::path& dir, std::vector<int> point_frames = {});
  // point_frames.csv's columns: iteration, index, x, y, z (robot frame), true_wall.
  static const std::vector<std::string>& point_columns();

  // The planes of one point frame with their truth (scored, and recorded when recording). An
  // end within cut_margin of the frustum's edge is flagged as cut by the field of view
  // (PlaneObject::a_cut, b_cut), as the plane sensor flags the ends its clip made: something the
  // sensor knows, not the truth.
  sim::PlaneSimFrame extract(const sim::PointSimFrame& frame);
  double last_ms() const { return last_ms_; }
  const ExtractionFrameScore& last_score() const { return last_score_; }
  // Closes em_frames.csv.
  void finish();
  // For manifest.json: the extractor and the run's medians and means.
  nlohmann::json describe() const;

 private:
  PlaneExtractorKind kind_;
  std::uint64_t seed_;
  std::unique_ptr<PlaneExtractor> extractor_;
  const std::vector<PlaneObject>& walls_;
  double end_tolerance_;
  // The sensor's field of view and how close to its edge an extracted end counts as cut by it.
  sim::ViewingFrustum frustum_;
  double cut_margin_;
  ExtractionScoreOptions score_options_;
  std::optional<CsvWriter> frames_;
  std::vector<int> point_frames_;  // sorted
  std::optional<CsvWriter> points_;
  double last_ms_ = 0;
  ExtractionFrameScore last_score_;
  std::vector<double> ms_;
  long long correct_ = 0, true_visible_ = 0, scored_planes_ = 0;
};

}  // namespace relslam::eval
