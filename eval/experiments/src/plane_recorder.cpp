#include "relslam/eval/experiments/plane_recorder.hpp"

#include "relslam/eval/metrics/trajectory_error.hpp"
#include "relslam/eval/metrics/truth_departure.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace relslam::eval {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

const std::filesystem::path& created(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  return dir;
}

std::vector<std::string> with_own(std::vector<std::string> columns, const std::vector<std::string>& own) {
  columns.insert(columns.end(), own.begin(), own.end());
  return columns;
}

bool finite(const PlanarPose& p) { return p.translation.allFinite() && std::isfinite(p.heading); }
bool finite(const PlaneObject& p) { return p.a.allFinite() && p.b.allFinite(); }

}  // namespace

const std::vector<ScoreColumn<PlaneIterationRow>>& plane_iteration_columns() {
  using R = PlaneIterationRow;
  static const std::vector<ScoreColumn<R>> columns = {
      {"iteration", "", "the frame's iteration k", [](const R& r) { return csv_field(r.iteration); }},
      {"map_error", "world", "sum over the mapped planes of the key-point error e_ends against their walls",
       [](const R& r) { return csv_field(r.map_error.sum); }},
      {"mean_map_error", "world", "map_error per scored plane; empty when none is scored",
       [](const R& r) { return r.map_error.scored > 0 ? csv_field(r.map_error.mean) : CsvField{}; }},
      {"position_error", "world", "distance of the estimated position from the true one",
       [](const R& r) { return r.pose_error ? csv_field(r.pose_error->position) : CsvField{}; }},
      {"heading_error_deg", "deg", "estimated - true heading",
       [](const R& r) { return r.pose_error ? csv_field(r.pose_error->heading_rad * kDeg) : CsvField{}; }},
      {"ex", "world", "estimate - truth, world x",
       [](const R& r) { return r.pose_error ? csv_field(r.pose_error->axes.x()) : CsvField{}; }},
      {"ez", "world", "estimate - truth, world z",
       [](const R& r) { return r.pose_error ? csv_field(r.pose_error->axes.y()) : CsvField{}; }},
      {"runtime_ms", "ms", "wall-clock time of the algorithm's step", [](const R& r) { return csv_field(r.runtime_ms); }},
      {"planes_in_map", "", "planes on the map", [](const R& r) { return csv_field(r.planes_in_map); }},
      {"visible_planes", "", "plane observations in the frame", [](const R& r) { return csv_field(r.visible_planes); }},
  };
  return columns;
}

PlaneRecorder::PlaneRecorder(std::unique_ptr<PlaneAlgorithm> algorithm, const std::vector<PlaneObject>& walls,
                             const std::vector<std::string>& source_columns, const std::filesystem::path& dir)
    : algorithm_(std::move(algorithm)),
      walls_(walls),
      dir_(created(dir)),
      iterations_(dir_ / "iterations.csv",
                  with_own(with_own(with_own(column_names(plane_iteration_columns()), algorithm_->iteration_columns()),
                                    algorithm_->scores_wrong_valid()
                                        ? std::vector<std::string>{"kp_checked", "kp_wrong", "wrong_valid"}
                                        : std::vector<std::string>{"kp_checked", "kp_wrong"}),
                           source_columns)),
      trajectory_(dir_ / "trajectory.tum") {
  if (algorithm_->claims_key_points())
    keypoints_.emplace(dir_ / "keypoints.csv",
                       std::vector<std::string>{"iteration", "group", "plane", "kp", "static", "ambiguous",
                                                "interval_start", "interval_end", "truth_correct"});
}

void PlaneRecorder::step(const PlaneFrame& observation, const PlaneTruthFrame& truth,
                         const std::vector<CsvField>& measured) {
  digest_.add(observation);
  if (!running()) return;  // failed: the rest of the stream is not processed
  const int k = observation.iteration;
  const std::optional<double> timed = timed_step(k, status_, [&] { algorithm_->step(observation); });
  if (!timed) return;
  const double runtime_ms = *timed;

  // Scoring, outside the timed region.
  algorithm_->read_out();
  const std::optional<PlanarPose> pose = algorithm_->pose();
  const std::vector<MappedPlane>& map = algorithm_->map();
  if ((pose && !finite(*pose)) || !std::all_of(map.begin(), map.end(), [](const auto& m) { return finite(m.second); })) {
    status_ = RunStatus::failed(k, "the estimate became NaN");
    return;
  }
  const std::vector<int>& assignment = algorithm_->assignment();
  for (std::size_t i = 0; i < truth.planes.size(); ++i) {
    walls_seen_.insert(truth.planes[i].wall_id);
    if (i < assignment.size()) votes_.add(assignment[i], truth.planes[i].wall_id);
  }
  last_map_error_ = plane_map_error(map, votes_, walls_);
  if (last_map_error_.scored > 0) mean_map_errors_.push_back(last_map_error_.mean);
  std::optional<PlanarPoseError> pose_error;
  if (pose && truth.pose_known) {
    pose_error = planar_pose_error(*pose, truth.world_T_robot);
    last_pose_error_ = pose_error;
    max_position_error_ = std::max(max_position_error_, pose_error->position);
  }
  if (pose) trajectory_.write(static_cast<double>(k), rigid_from_planar(*pose));
  estimates_.push_back(pose);
  truths_.push_back(truth.pose_known ? std::optional<PlanarPose>(truth.world_T_robot) : std::nullopt);
  iterations_done_.push_back(k);
  runtimes_ms_.push_back(runtime_ms);

  fields_.clear();
  append_fields(plane_iteration_columns(), {k, last_map_error_, pose_error, runtime_ms, map.size(), observation.planes.size()},
                fields_);
  algorithm_->iteration_fields(fields_);
  // Key-point correctness: a claim is right when the ends it says are real are the
  // wall's real ends in this observation.
  long long checked = 0, wrong = 0;
  if (keypoints_)
    for (const KeyPointClaim& c : algorithm_->key_point_claims()) {
      if (c.observation < 0 || static_cast<std::size_t>(c.observation) >= truth.planes.size()) continue;
      const PlaneTruth& t = truth.planes[static_cast<std::size_t>(c.observation)];
      const bool correct = c.key_point == 1 ? t.a_is_wall_end : t.b_is_wall_end;
      ++checked;
      wrong += !correct;
      keypoints_->row(static_cast<long long>(k), c.group, c.plane, c.key_point, c.is_static, c.ambiguous,
                      c.interval_start, c.interval_end, correct);
    }
  key_points_checked_ += checked;
  key_points_wrong_ += wrong;
  wrong_key_point_iterations_ += wrong > 0;
  fields_.insert(fields_.end(), {CsvField{checked}, CsvField{wrong}});
  if (algorithm_->scores_wrong_valid()) {  // a valid pose off the truth by more than the bound
    const bool wrong_valid = pose_error && pose_error->position > kWrongValidBound;
    wrong_valid_ += wrong_valid;
    fields_.push_back(CsvField{static_cast<long long>(wrong_valid)});
  }
  fields_.insert(fields_.end(), measured.begin(), measured.end());
  iterations_.row_fields(fields_);
}

PlaneRecorder::MapCounts PlaneRecorder::write_planes_table() {
  const std::vector<MappedPlane>& map = algorithm_->map();
  std::vector<std::string> columns = {"id",    "true_wall", "kp1_x",     "kp1_z",  "kp2_x",     "kp2_z",
                                      "length", "e_ends",   "e_ang_deg", "e_perp", "len_ratio"};
  CsvWriter planes(dir_ / "planes.csv", with_own(columns, algorithm_->plane_columns()));
  // A duplicate is a second plane for the same face of a wall: with back faces in view (no
  // culling, Rule 10 on) a wall's front and back are two planes by design (thesis Fig. 72).
  std::map<std::pair<int, bool>, int> planes_per_face;
  std::set<int> walls_mapped;
  for (const auto& [id, plane] : map) {
    const int wall = votes_.wall_of(id);
    const bool known = wall >= 0 && static_cast<std::size_t>(wall) < walls_.size();
    if (known) {
      walls_mapped.insert(wall);
      ++planes_per_face[{wall, plane.normal().dot(walls_[static_cast<std::size_t>(wall)].normal()) < 0}];
    }
    const std::optional<PlaneError> e =
        known ? std::optional<PlaneError>(plane_error(plane, walls_[static_cast<std::size_t>(wall)])) : std::nullopt;
    fields_ = {static_cast<long long>(id),
               known ? CsvField{static_cast<long long>(wall)} : CsvField{},
               plane.a.x(),
               plane.a.y(),
               plane.b.x(),
               plane.b.y(),
               plane.length(),
               e ? CsvField{e->ends} : CsvField{},
               e ? CsvField{e->angle_rad * kDeg} : CsvField{},
               e ? CsvField{e->perpendicular} : CsvField{},
               e ? CsvField{e->length_ratio} : CsvField{}};
    algorithm_->plane_fields(id, fields_);
    planes.row_fields(fields_);
  }
  planes.close();
  MapCounts counts;
  counts.walls_mapped = static_cast<int>(walls_mapped.size());
  for (const auto& [face, n] : planes_per_face) counts.duplicates += n - 1;
  return counts;
}

void PlaneRecorder::score_trajectory(SummaryRow& row) const {
  std::vector<Rigid3> estimated, true_poses;
  for (std::size_t i = 0; i < estimates_.size(); ++i)
    if (estimates_[i] && truths_[i]) {
      estimated.push_back(rigid_from_planar(*estimates_[i]));
      true_poses.push_back(rigid_from_planar(*truths_[i]));
    }
  row.trajectory = trajectory_error(estimated, true_poses);
  if (std::none_of(truths_.begin(), truths_.end(), [](const auto& t) { return t.has_value(); })) {
    const double unknown = std::nan("");  // no true path: nothing to score, not a zero error
    row.trajectory = {unknown, unknown, unknown, unknown};
  }
}

PlanarScores PlaneRecorder::planar_scores(int walls_mapped) {
  const auto with_pose = std::count_if(estimates_.begin(), estimates_.end(), [](const auto& e) { return e.has_value(); });
  PlanarScores scores;
  scores.final_heading_error_deg = last_pose_error_ ? last_pose_error_->heading_rad * kDeg : std::nan("");
  scores.max_position_error = max_position_error_;
  scores.pose_valid_fraction =
      estimates_.empty() ? 0.0 : static_cast<double>(with_pose) / static_cast<double>(estimates_.size());
  scores.walls_mapped = walls_mapped;
  walls_seen_.erase(-1);
  scores.walls_seen = static_cast<int>(walls_seen_.size());
  scores.key_point_accuracy = key_points_checked_ > 0 ? 1.0 - static_cast<double>(key_points_wrong_) /
                                                                  static_cast<double>(key_points_checked_)
                                                      : std::nan("");
  scores.wrong_key_point_iterations = wrong_key_point_iterations_;
  return scores;
}

std::string PlaneRecorder::departure() const {
  std::vector<Eigen::Vector3d> path;
  std::vector<PositionErrorAt> errors;
  for (std::size_t i = 0; i < estimates_.size(); ++i) {
    if (truths_[i]) path.push_back(rigid_from_planar(*truths_[i]).translation);
    errors.push_back({iterations_done_[i], estimates_[i] && truths_[i]
                                               ? std::optional<double>(planar_pose_error(*estimates_[i], *truths_[i]).position)
                                               : std::nullopt});
  }
  return truth_departure(errors, path_extent(path));
}

SummaryRow PlaneRecorder::finish() {
  iterations_.close();
  trajectory_.close();
  if (keypoints_) keypoints_->close();
  const MapCounts counts = write_planes_table();
  algorithm_->write_tables(dir_);

  SummaryRow row;
  row.algorithm = name();
  row.status = status_;
  // An estimate that stayed far from the truth has not mapped the walls (truth_departure.hpp).
  if (const std::string left = running() ? departure() : ""; !left.empty()) row.status = RunStatus::lost(left);
  row.iterations = static_cast<int>(estimates_.size());
  // Without true walls (recorded planes) there is no map error, not a zero one.
  row.final_landmark_error = walls_.empty() ? std::nan("") : last_map_error_.sum;
  row.final_mean_landmark_error = last_map_error_.scored > 0 ? last_map_error_.mean : std::nan("");
  double sum = 0;
  for (double e : mean_map_errors_) sum += e;
  row.mean_landmark_error = mean_map_errors_.empty() ? std::nan("") : sum / mean_map_errors_.size();
  row.final_position_error = last_pose_error_ ? last_pose_error_->position : std::nan("");
  score_trajectory(row);
  row.landmarks_on_map = static_cast<int>(algorithm_->map().size());
  row.duplicates = counts.duplicates;
  row.runtime = runtime_stats(runtimes_ms_);
  row.peak_rss_mb = peak_rss_mb();
  row.input_digest = digest_.hex();
  row.planar = planar_scores(counts.walls_mapped);
  row.own_columns = algorithm_->summary_columns();
  algorithm_->summary_fields(row.own_fields);
  if (algorithm_->scores_wrong_valid()) {
    row.own_columns.push_back("wrong_valid");
    row.own_fields.push_back(CsvField{wrong_valid_});
  }
  return row;
}

}  // namespace relslam::eval
