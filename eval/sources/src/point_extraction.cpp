#include "relslam/eval/sources/point_extraction.hpp"

#include "relslam/eval/sources/make_plane_extractor.hpp"

#include "relslam/em/em_random.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace relslam::eval {
namespace {

double median(std::vector<double> values) {
  if (values.empty()) return std::nan("");
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

}  // namespace

sim::PointSensorOptions point_sensor_options(const LoadedScenario& loaded, const sim::PlaneSensorOptions& map_sensor) {
  sim::PointSensorOptions o = sim::PointSensorOptions::matching(map_sensor);
  o.sigma = loaded.scenario.planar.noise.point_sigma;
  return o;
}

const std::vector<std::string>& PointExtraction::columns() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out = {"iteration"};
    out.insert(out.end(), extraction_score_columns().begin(), extraction_score_columns().end());
    out.push_back("ms");
    return out;
  }();
  return names;
}

PointExtraction::PointExtraction(const LoadedScenario& loaded, const std::vector<PlaneObject>& walls,
                                 const sim::PointSensorOptions& sensor)
    : kind_(loaded.scenario.extraction.extractor),
      seed_(loaded.scenario.seed),
      walls_(walls),
      // Thesis 4.5: an extracted end is a real wall end within max(0.5 s_pt, 3 σ_pt).
      end_tolerance_(std::max(0.5 * sensor.spacing, 3.0 * sensor.sigma)),
      // The last point found on a wall the frustum cuts lies within about one grid cell of the
      // edge (s_pt, jittered) and is moved by the noise (3 σ_pt) [C].
      frustum_(sensor.frustum),
      cut_margin_(sensor.spacing * (1.0 + sensor.jitter) + 3.0 * sensor.sigma),
      score_options_(ExtractionScoreOptions::for_em(loaded.scenario.extraction.em)) {
  const ExtractorSettings settings{loaded.scenario.extraction.em, loaded.scenario.extraction.ransac};
  try {
    extractor_ = make_plane_extractor(kind_, settings);
  } catch (const std::invalid_argument& e) {
    throw loaded.error("relative_plane.extractor", e.what());
  }
}

const std::vector<std::string>& PointExtraction::point_columns() {
  static const std::vector<std::string> names = {"iteration", "index", "x", "y", "z", "true_wall"};
  return names;
}

void PointExtraction::record_into(const std::filesystem::path& dir, std::vector<int> point_frames) {
  frames_.emplace(dir / "em_frames.csv", columns());
  std::sort(point_frames.begin(), point_frames.end());
  point_frames.erase(std::unique(point_frames.begin(), point_frames.end()), point_frames.end());
  point_frames_ = std::move(point_frames);
  if (!point_frames_.empty()) points_.emplace(dir / "point_frames.csv", point_columns());
}

sim::PlaneSimFrame PointExtraction::extract(const sim::PointSimFrame& frame) {
  const PlanarPointFrame& points = frame.observation;
  if (points_ && std::binary_search(point_frames_.begin(), point_frames_.end(), points.iteration))
    for (std::size_t i = 0; i < points.points.size(); ++i) {
      const Eigen::Vector3d& p = points.points[i];
      points_->row(points.iteration, static_cast<long long>(i), p.x(), p.y(), p.z(), frame.truth.wall_ids[i]);
    }
  const auto start = std::chrono::steady_clock::now();
  em::ExtractedPlanes planes = extractor_->extract(points, em::em_frame_seed(seed_, points.iteration));
  last_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ms_.push_back(last_ms_);

  sim::PlaneSimFrame out;
  out.observation = std::move(planes.frame);
  out.observation.iteration = points.iteration;
  for (PlaneObject& p : out.observation.planes) {
    p.a_cut = frustum_.depth(p.a) < cut_margin_;
    p.b_cut = frustum_.depth(p.b) < cut_margin_;
  }
  out.truth.iteration = points.iteration;
  out.truth.world_T_robot = frame.truth.world_T_robot;
  std::vector<em::TrueWallEnds> ends;
  for (std::size_t id = 0; id < walls_.size(); ++id)
    ends.push_back({static_cast<int>(id), frame.truth.world_T_robot.inverse_apply(walls_[id].a),
                    frame.truth.world_T_robot.inverse_apply(walls_[id].b)});
  for (std::size_t i = 0; i < out.observation.planes.size(); ++i)
    out.truth.planes.push_back(em::extracted_plane_truth(out.observation.planes[i], planes.support[i],
                                                         frame.truth.wall_ids, ends, end_tolerance_));

  last_score_ = score_extraction(points.points, frame.truth.wall_ids, walls_, frame.truth.world_T_robot,
                                 out.observation.planes, planes.support, score_options_);
  const ExtractionFrameScore& s = last_score_;
  correct_ += s.counts.correct;
  true_visible_ += s.true_visible;
  scored_planes_ += s.planes - s.ignored_planes;
  if (frames_) {
    std::vector<CsvField> fields = {CsvField{static_cast<long long>(points.iteration)}};
    append_score_fields(s, fields);
    fields.emplace_back(last_ms_);
    frames_->row_fields(fields);
  }
  return out;
}

void PointExtraction::finish() {
  if (frames_) frames_->close();
  if (points_) points_->close();
}

nlohmann::json PointExtraction::describe() const {
  auto ratio = [](long long a, long long b) { return b > 0 ? static_cast<double>(a) / static_cast<double>(b) : 1.0; };
  return {{"extractor", std::string(to_string(kind_))},
          {"frames", ms_.size()},
          {"median_ms", median(ms_)},
          {"recall", ratio(correct_, true_visible_)},
          {"precision", ratio(correct_, scored_planes_)}};
}

}  // namespace relslam::eval
