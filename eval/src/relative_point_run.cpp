// The Relative Point algorithm (libslam's RltMapper) as one algorithm of a run.
#include "relslam/eval/algorithm_run.hpp"
#include "ekf2d_run.hpp"
#include "ekf6d_run.hpp"
#include "relslam/eval/csv_writer.hpp"
#include "relslam/eval/iteration_table.hpp"
#include "relslam/eval/run_scorer.hpp"
#include "relslam/eval/scenario.hpp"
#include "relslam/eval/tum_writer.hpp"
#include "relslam/point/rlt_mapper.hpp"

#include <chrono>
#include <cstdio>

namespace relslam::eval {
namespace {

using point::RltMapper;
using point::RltPoint;

std::string level_of(const RltPoint& p, const RltMapper& mapper) {
  if (p.merged) return "merged";
  if (p.dynamic) return "dynamic";
  if (!p.has_global) return "none";
  switch (mapper.groups()[p.owner].level()) {
    case point::GroupLevel::Temporary: return "temporary";
    case point::GroupLevel::Final: return "final";
    case point::GroupLevel::Level3: return "level3";
  }
  return "?";
}

class RelativePointRun final : public AlgorithmRun {
 public:
  RelativePointRun(const Scenario& scenario, const LandmarkTruth& truth, const std::filesystem::path& dir)
      : dir_(dir),
        truth_dynamic_(truth.positions.size(), false),
        mapper_(scenario.relative_point),
        scorer_(truth),
        iterations_(dir / "iterations.csv",
                    {"t_init_ms", "t_load_ms", "t_compute_ms", "t_create_ms", "t_pose_ms", "rlt_points", "groups",
                     "final_groups", "groups_alive", "temporary_groups_alive", "new_points", "local_matches",
                     "global_matches", "pose_source", "t_merge_ms", "t_binning_ms", "binning_comparisons",
                     "dynamic_flagged", "merges", "mean_group_members"}),
        trajectory_(dir / "trajectory.tum") {
    for (int id : truth.dynamic_ids) truth_dynamic_[id] = true;
  }

  const std::string& name() const override { return name_; }

  void step(const ObservationFrame& observation, const TruthFrame& truth) override {
    digest_.add(observation);
    if (!failure_.empty()) return;
    const auto start = std::chrono::steady_clock::now();
    point::StepResult r;
    try {
      r = mapper_.step(observation);
    } catch (const std::exception& e) {  // a bad frame ends this algorithm's run, not the batch
      failure_ = "failed at iteration " + std::to_string(observation.iteration) + ": " + e.what();
      return;
    }
    const double runtime_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

    // Scoring, outside the timed region.
    scorer_.associate(r.assignment, truth.landmark_ids);
    const auto& points = mapper_.points();
    const IterationScore s = scorer_.score(r.iteration, r.world_T_robot, truth, r.changed,
                                           [&](int id) -> std::optional<Eigen::Vector3d> {
                                             if (!points[id].on_map()) return std::nullopt;
                                             return points[id].global;
                                           },
                                           runtime_ms);
    const point::GroupStats g = mapper_.group_stats();
    const point::StepTimings& t = r.timings;
    iterations_.row(r.iteration, s, runtime_ms, observation.points.size(), t.init_ms, t.load_ms, t.compute_ms,
                    t.create_ms, t.pose_ms, points.size(), g.created, g.final_created, g.alive, g.temporary_alive, r.new_points, r.local_matches, r.global_matches, pose_source(r.pose_source),
                    t.merge_ms, t.binning_ms, r.binning_comparisons, g.dynamic_points, g.merged_points,
                    g.alive > 0 ? std::optional(static_cast<double>(g.alive_members) / g.alive) : std::nullopt);
    trajectory_.write(static_cast<double>(r.iteration), r.world_T_robot);
  }

  SummaryRow finish() override {
    iterations_.close();
    trajectory_.close();
    CsvWriter landmarks(dir_ / "landmarks.csv", {"id", "x", "y", "z", "true_id", "error", "level", "observations",
                                                 "first_iteration", "last_iteration", "owner_group", "dynamic_flagged",
                                                 "true_dynamic", "merged_into"});
    std::vector<int> on_map;
    for (const RltPoint& p : mapper_.points()) {
      const bool mapped = p.has_global;
      if (p.on_map()) on_map.push_back(p.id);
      const std::optional<double> x = mapped ? std::optional(p.global.x()) : std::nullopt;
      const std::optional<double> y = mapped ? std::optional(p.global.y()) : std::nullopt;
      const std::optional<double> z = mapped ? std::optional(p.global.z()) : std::nullopt;
      const int truth = scorer_.majority_truth(p.id);
      landmarks.row(p.id, x, y, z, truth, scorer_.error_of(p.id), level_of(p, mapper_), p.interval.total(),
                    p.interval.first(), p.interval.last(), p.owner >= 0 ? std::optional(p.owner) : std::nullopt,
                    p.dynamic, is_truly_dynamic(truth),
                    p.merged ? std::optional(p.merged_into) : std::nullopt);
    }
    landmarks.close();
    SummaryRow row = summary_over(static_cast<int>(scorer_.scored()));
    row.landmarks_on_map = static_cast<int>(on_map.size());
    row.duplicates = scorer_.duplicates(on_map);
    row.peak_rss_mb = peak_rss_mb();
    return row;
  }

  // Without truth landmarks (a rawlog run) the ids are the log's own, and nothing is known to move.
  bool is_truly_dynamic(int truth) const {
    return truth >= 0 && static_cast<std::size_t>(truth) < truth_dynamic_.size() && truth_dynamic_[truth];
  }

  const std::vector<Rigid3>& trajectory() const override { return scorer_.estimates(); }
  std::vector<Eigen::Vector3d> map() const override {
    std::vector<Eigen::Vector3d> out;
    for (const RltPoint& p : mapper_.points())
      if (p.on_map()) out.push_back(p.global);
    return out;
  }

  SummaryRow summary_over(int iterations) const override {
    SummaryRow row;
    row.algorithm = name_;
    row.status = !failure_.empty() ? failure_ : mapper_.failure().empty() ? "ok" : "failed: " + mapper_.failure();
    scorer_.fill(row, static_cast<std::size_t>(iterations));
    row.input_digest = digest_.hex();
    return row;
  }

 private:
  static const char* pose_source(point::PoseSource s) {
    switch (s) {
      case point::PoseSource::Start: return "start";
      case point::PoseSource::MappedPoints: return "mapped";
      case point::PoseSource::UnmappedPoints: return "unmapped";
      case point::PoseSource::Held: return "held";
      case point::PoseSource::Odometry: return "odometry";
    }
    return "?";
  }

  std::string name_ = "relative_point";
  std::filesystem::path dir_;
  std::vector<bool> truth_dynamic_;  // by true landmark id
  RltMapper mapper_;
  RunScorer scorer_;
  IterationTable iterations_;
  TumWriter trajectory_;
  FrameDigest digest_;
  std::string failure_;  // an exception ended the run
};

}  // namespace


void FrameDigest::add(const ObservationFrame& frame) {
  // FNV-1a over the iteration and the raw bytes of the points.
  auto mix = [this](const void* data, std::size_t n) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) state_ = (state_ ^ bytes[i]) * 0x100000001b3ULL;
  };
  mix(&frame.iteration, sizeof frame.iteration);
  for (const Eigen::Vector3d& p : frame.points) mix(p.data(), 3 * sizeof(double));
  if (frame.odometry) {
    mix(frame.odometry->rotation.data(), 9 * sizeof(double));
    mix(frame.odometry->translation.data(), 3 * sizeof(double));
  }
}

std::string FrameDigest::hex() const {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(state_));
  return text;
}

std::unique_ptr<AlgorithmRun> make_algorithm_run(const std::string& name, const Scenario& scenario,
                                                 const LandmarkTruth& truth, const RangeBearingSensor& sensor,
                                                 const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir / name);
  if (name == "relative_point") return std::make_unique<RelativePointRun>(scenario, truth, dir / name);
  if (name == "ekf6d") return make_ekf6d_run(scenario.ekf6d, sensor, truth, dir / name);
  if (name == "ekf2d" || name == "ekf2d_no_odometry")
    return make_ekf2d_run(scenario.ekf2d, name == "ekf2d", sensor, truth, dir / name);
  throw std::logic_error("make_algorithm_run: unknown algorithm " + name);
}

}  // namespace relslam::eval
