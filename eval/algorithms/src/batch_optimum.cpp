// The batch optimum (docs/batch_optimum.md): every frame is stored as it comes, with a start
// pose (the truth perturbed, or a Relative Point run's pose); after the last frame finish()
// solves the full least-squares problem once (optimum_problem.hpp). Until then its pose and map
// are the start; afterwards the solved trajectory replaces the steps' poses (revised_trajectory)
// and the map is the solved landmarks.
#include "batch_optimum.hpp"

#include "map_landmark_columns.hpp"
#include "optimum_problem.hpp"

#include "relslam/eval/algorithms/map_frame_gauge.hpp"
#include "relslam/point/rlt_mapper.hpp"
#include "relslam/relax/ceres_relaxation.hpp"
#include "relslam/sim/random.hpp"

#include <cmath>
#include <map>

namespace relslam::eval {
namespace {

// A landmark as landmarks.csv sees it.
struct LandmarkRow {
  int id;
  const Eigen::Vector3d& position;
  int observations;
  const LandmarkScore& score;
  const char* level = "optimum";  // the solved map's
};

// The map's columns and the observations behind each landmark.
const Columns<LandmarkRow> kLandmarkColumns = [] {
  Columns<LandmarkRow> columns = map_landmark_columns<LandmarkRow>();
  columns.push_back({"observations", [](const LandmarkRow& r) { return csv_field(r.observations); }});
  return columns;
}();

// The summary's own columns: the solve, once per run.
const Columns<OptimumReport> kSummaryColumns = {
    {"solve_s", [](const OptimumReport& r) { return csv_field(r.solve_s); }},
    {"solver_iterations", [](const OptimumReport& r) { return csv_field(r.solver_iterations); }},
    {"initial_cost", [](const OptimumReport& r) { return csv_field(r.initial_cost); }},
    {"final_cost", [](const OptimumReport& r) { return csv_field(r.final_cost); }},
};

// A rotation of `sigma_rad` per axis about a random axis, and a shift of `sigma` per axis,
// drawn from the scenario's seed and the step (the same start whatever else runs).
Rigid3 perturbed(const Rigid3& pose, const BatchOptimumOptions& o, std::uint64_t seed, int step) {
  sim::RandomSequence rng(seed, sim::Stream::OptimumStart, static_cast<std::uint64_t>(step));
  Eigen::Vector3d angle, shift;
  for (int i = 0; i < 3; ++i) angle[i] = o.start_sigma_rotation_rad * rng.gaussian();
  for (int i = 0; i < 3; ++i) shift[i] = o.start_sigma_position * rng.gaussian();
  Rigid3 out = pose;
  if (angle.norm() > 0) out.rotation = rotation_about(angle.normalized(), angle.norm()) * pose.rotation;
  out.translation += shift;
  return out;
}

// The observations' noise model: the sensor's, or the EKF's sensor model (range, yaw, pitch).
ObservationNoise noise_of(const BatchOptimumOptions& options, const Ekf6dOptions& ekf,
                          const RangeBearingSensor& sensor) {
  if (options.noise_model == OptimumModel::Own) return observation_noise(sensor);
  return {true, ekf.std_range, ekf.std_yaw_rad, ekf.std_pitch_rad};
}

// The EKF's constant-position model as a step measurement: the pose stays, with stds_q's
// x, y, z (their mean: one deviation per axis) and its quaternion's vector part, whose
// deviation is half the angle's per axis (small angles) [C].
StepMeasurement constant_position(const Ekf6dOptions& ekf) {
  const std::vector<double>& q = ekf.stds_q;
  return {Rigid3::identity(), (q[0] + q[1] + q[2]) / 3.0, 2.0 * (q[4] + q[5] + q[6]) / 3.0};
}

class BatchOptimum final : public Algorithm {
 public:
  BatchOptimum(const BatchOptimumOptions& options, const Ekf6dOptions& ekf,
               const point::PointSlamOptions& relative_point, const RangeBearingSensor& sensor, std::uint64_t seed)
      : options_(options), noise_(noise_of(options, ekf, sensor)), motion_(constant_position(ekf)), seed_(seed) {
    if (options.start == OptimumStart::RelativePoint || options.association == OptimumAssociation::RelativePoint)
      mapper_.emplace(relative_point, relax::solve_relaxation);
    if (options.motion_model == OptimumMotion::ConstantVelocity)
      problem_.constant_velocity = ConstantVelocity{options.velocity_std_xyz, options.velocity_std_angle_rad};
  }

  const std::string& name() const override { return name_; }

  void step(const ObservationFrame& observation, const TruthFrame& truth) override {
    const int k = static_cast<int>(problem_.world_T_robot.size());
    if (mapper_) {
      relative_step_ = mapper_->step(observation);
      relative_gauge_.observe(observation.iteration, mapper_->first_iteration(), truth);
    }
    problem_.world_T_robot.push_back(start_pose(truth, k));
    problem_.steps.push_back(step_measurement(observation, k));
    assignment_.assign(observation.points.size(), -1);
    changed_.clear();
    // The landmark's id: the truth's (a rawlog's own ids) or Relative Point's, -1 unknown.
    const std::vector<int>& ids =
        options_.association == OptimumAssociation::Known ? truth.landmark_ids : relative_step_.assignment;
    for (std::size_t i = 0; i < observation.points.size(); ++i) {
      const int id = i < ids.size() ? ids[i] : -1;
      if (id < 0) continue;
      auto [at, added] = index_of_.try_emplace(id, static_cast<int>(problem_.landmarks.size()));
      if (added) {
        problem_.landmarks.push_back(problem_.world_T_robot.back() * observation.points[i]);
        observations_of_.push_back(0);
        id_of_.push_back(id);
        changed_.push_back(id);
      }
      ++observations_of_[at->second];
      problem_.observations.push_back({k, at->second, observation.points[i]});
      assignment_[i] = id;
    }
  }

  void finish() override {
    settle_relative_point_start();
    follow_relative_point_merges();
    report_ = solve_optimum(problem_, noise_, options_);
    solved_ = true;
    changed_.clear();
    for (const auto& [id, index] : index_of_) changed_.push_back(id);
  }
  std::vector<Rigid3> revised_trajectory() const override {
    return solved_ ? problem_.world_T_robot : std::vector<Rigid3>{};
  }
  std::string failure() const override {
    return solved_ && !report_.usable ? "the least-squares solve failed: " + report_.termination : "";
  }

  Rigid3 pose() const override { return problem_.world_T_robot.back(); }
  const std::vector<int>& assignment() const override { return assignment_; }
  const std::vector<int>& changed() const override { return changed_; }
  std::optional<Eigen::Vector3d> position(int id) const override {
    const auto at = index_of_.find(id);
    if (at == index_of_.end()) return std::nullopt;
    return problem_.landmarks[at->second];
  }
  std::vector<int> map_ids() const override {
    std::vector<int> ids;
    for (const auto& [id, index] : index_of_) ids.push_back(id);
    return ids;
  }

  std::vector<std::string> iteration_columns() const override { return {}; }
  void iteration_fields(std::vector<CsvField>&) const override {}
  std::vector<std::string> landmark_columns() const override { return column_names(kLandmarkColumns); }
  void landmark_rows(const std::function<LandmarkScore(int)>& score,
                     const std::function<void(const std::vector<CsvField>&)>& row) const override {
    std::vector<CsvField> fields;
    for (const auto& [id, index] : index_of_) {
      const LandmarkScore s = score(id);
      fields.clear();
      append_fields(kLandmarkColumns, {id, problem_.landmarks[index], observations_of_[index], s}, fields);
      row(fields);
    }
  }
  std::vector<std::string> summary_columns() const override { return column_names(kSummaryColumns); }
  void summary_fields(std::vector<CsvField>& out) const override { append_fields(kSummaryColumns, report_, out); }

 private:
  // The first pose is the gauge: the truth's (the world frame is the robot's first frame), as
  // every estimator's map frame; the others start perturbed or where Relative Point put them.
  Rigid3 start_pose(const TruthFrame& truth, int k) {
    const Rigid3 gauge = truth.pose_known ? truth.world_T_robot : Rigid3::identity();
    if (options_.start == OptimumStart::RelativePoint) return k == 0 ? gauge : relative_gauge_.pose(relative_step_.world_T_robot);
    if (k == 0 || !truth.pose_known) return k == 0 ? gauge : problem_.world_T_robot.back();
    return perturbed(truth.world_T_robot, options_, seed_, k);
  }

  // Between the previous frame and this one: its odometry when used, else the EKF's motion model
  // when asked for, else nothing (the constant-velocity prior spans three frames: in problem_).
  std::optional<StepMeasurement> step_measurement(const ObservationFrame& observation, int k) const {
    if (k == 0) return std::nullopt;
    if (options_.use_odometry && observation.odometry)
      return StepMeasurement{*observation.odometry, options_.odometry_std_xyz, options_.odometry_std_angle_rad};
    if (options_.motion_model == OptimumMotion::Ekf6d) return motion_;
    return std::nullopt;
  }

  // Relative Point has no pose before its map frame (a sparse start moves it later): those steps
  // start at its first pose, and every landmark again where its first sighting puts it.
  void settle_relative_point_start() {
    if (options_.start != OptimumStart::RelativePoint) return;
    const std::size_t first = std::min(relative_gauge_.steps_before(), problem_.world_T_robot.size() - 1);
    for (std::size_t k = 1; k < first; ++k) problem_.world_T_robot[k] = problem_.world_T_robot[first];
    std::vector<bool> placed(problem_.landmarks.size(), false);
    for (const OptimumObservation& o : problem_.observations) {
      if (placed[o.landmark]) continue;
      problem_.landmarks[o.landmark] = problem_.world_T_robot[o.pose] * o.p_robot;
      placed[o.landmark] = true;
    }
  }

  // With Relative Point's association, its final word on each point: a merged point's
  // observations go to the point it was merged into (thesis 6.5.2), a point it flagged dynamic
  // (6.5.3) leaves the problem with its observations.
  void follow_relative_point_merges() {
    if (options_.association != OptimumAssociation::RelativePoint) return;
    const std::vector<point::RltPoint>& points = mapper_->points();
    const auto kept_id = [&](int id) {
      while (points[id].merged && points[id].merged_into != point::kNone) id = points[id].merged_into;
      return points[id].dynamic || points[id].merged ? -1 : id;
    };
    std::map<int, int> index_of;
    OptimumProblem solved{problem_.world_T_robot, {}, {}, problem_.steps, problem_.constant_velocity};
    std::vector<int> observations_of;
    for (const OptimumObservation& o : problem_.observations) {
      const int id = kept_id(id_of_[o.landmark]);
      if (id < 0) continue;
      auto [at, added] = index_of.try_emplace(id, static_cast<int>(solved.landmarks.size()));
      if (added) {  // where its first sighting puts it
        solved.landmarks.push_back(problem_.world_T_robot[o.pose] * o.p_robot);
        observations_of.push_back(0);
      }
      ++observations_of[at->second];
      solved.observations.push_back({o.pose, at->second, o.p_robot});
    }
    problem_ = std::move(solved);
    index_of_ = std::move(index_of);
    observations_of_ = std::move(observations_of);
  }

  std::string name_ = "batch_optimum";
  BatchOptimumOptions options_;
  ObservationNoise noise_;
  StepMeasurement motion_;  // motion_model ekf6d
  std::uint64_t seed_;
  std::optional<point::RltMapper> mapper_;  // start or association relative_point only
  point::StepResult relative_step_;          // its latest step
  MapFrameGauge relative_gauge_;
  OptimumProblem problem_;
  std::map<int, int> index_of_;  // landmark id -> index in problem_.landmarks
  std::vector<int> id_of_;       // index in problem_.landmarks -> landmark id
  std::vector<int> observations_of_;
  std::vector<int> assignment_, changed_;
  OptimumReport report_;
  bool solved_ = false;
};

}  // namespace

std::unique_ptr<Algorithm> make_batch_optimum(const BatchOptimumOptions& options, const Ekf6dOptions& ekf,
                                              const point::PointSlamOptions& relative_point,
                                              const RangeBearingSensor& sensor, std::uint64_t seed) {
  return std::make_unique<BatchOptimum>(options, ekf, relative_point, sensor, seed);
}

}  // namespace relslam::eval
