// The Relative Point algorithm (libslam's RltMapper, thesis Chapter 3 and 6) as an algorithm of
// a run: its per-component timings and group counts as iterations.csv columns, each RltPoint
// (mapped or not) as a landmarks.csv row.
#include "relative_point.hpp"

#include "relslam/eval/algorithms/lost_pose.hpp"
#include "relslam/eval/algorithms/map_frame_gauge.hpp"
#include "relslam/point/rlt_mapper.hpp"
#include "relslam/relax/ceres_relaxation.hpp"

namespace relslam::eval {
namespace {

using point::RltMapper;
using point::RltPoint;

const char* level_of(const RltPoint& p, const RltMapper& mapper) {
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

const char* pose_source(point::PoseSource s) {
  switch (s) {
    case point::PoseSource::Start: return "start";
    case point::PoseSource::MappedPoints: return "mapped";
    case point::PoseSource::UnmappedPoints: return "unmapped";
    case point::PoseSource::TwoPoints: return "two_points";
    case point::PoseSource::OnePoint: return "one_point";
    case point::PoseSource::TwoUnmappedPoints: return "two_unmapped";
    case point::PoseSource::OneUnmappedPoint: return "one_unmapped";
    case point::PoseSource::Held: return "held";
    case point::PoseSource::Odometry: return "odometry";
  }
  return "?";
}

// Where a pose not registered to the map came from, for the lost status (lost_pose.hpp); "" for
// the map frame and registrations to mapped points (two with the latest rotation included).
std::string unregistered_origin(point::PoseSource s) {
  switch (s) {
    case point::PoseSource::Start:
    case point::PoseSource::MappedPoints:
    case point::PoseSource::TwoPoints: return "";
    case point::PoseSource::UnmappedPoints: return "unmapped points";
    case point::PoseSource::TwoUnmappedPoints: return "two unmapped points";
    case point::PoseSource::OneUnmappedPoint: return "one unmapped point";
    case point::PoseSource::OnePoint: return "one mapped point";
    case point::PoseSource::Held: return "the held pose";
    case point::PoseSource::Odometry: return "odometry";
  }
  return "?";
}

// One iteration as iterations.csv sees it.
struct IterationRow {
  const point::StepResult& step;
  const point::GroupStats& groups;
  std::size_t rlt_points;
};

const Columns<IterationRow> kIterationColumns = {
    {"t_init_ms", [](const IterationRow& r) { return csv_field(r.step.timings.init_ms); }},
    {"t_load_ms", [](const IterationRow& r) { return csv_field(r.step.timings.load_ms); }},
    {"t_compute_ms", [](const IterationRow& r) { return csv_field(r.step.timings.compute_ms); }},
    {"t_create_ms", [](const IterationRow& r) { return csv_field(r.step.timings.create_ms); }},
    {"t_pose_ms", [](const IterationRow& r) { return csv_field(r.step.timings.pose_ms); }},
    {"rlt_points", [](const IterationRow& r) { return csv_field(r.rlt_points); }},
    {"groups", [](const IterationRow& r) { return csv_field(r.groups.created); }},
    {"final_groups", [](const IterationRow& r) { return csv_field(r.groups.final_created); }},
    {"groups_alive", [](const IterationRow& r) { return csv_field(r.groups.alive); }},
    {"temporary_groups_alive", [](const IterationRow& r) { return csv_field(r.groups.temporary_alive); }},
    {"new_points", [](const IterationRow& r) { return csv_field(r.step.new_points); }},
    {"local_matches", [](const IterationRow& r) { return csv_field(r.step.local_matches); }},
    {"global_matches", [](const IterationRow& r) { return csv_field(r.step.global_matches); }},
    {"pose_source", [](const IterationRow& r) { return csv_field(pose_source(r.step.pose_source)); }},
    {"t_merge_ms", [](const IterationRow& r) { return csv_field(r.step.timings.merge_ms); }},
    {"t_binning_ms", [](const IterationRow& r) { return csv_field(r.step.timings.binning_ms); }},
    {"binning_comparisons", [](const IterationRow& r) { return csv_field(r.step.binning_comparisons); }},
    {"dynamic_flagged", [](const IterationRow& r) { return csv_field(r.groups.dynamic_points); }},
    {"merges", [](const IterationRow& r) { return csv_field(r.groups.merged_points); }},
    // Members per alive group (thesis Fig 123).
    {"mean_group_members",
     [](const IterationRow& r) {
       return r.groups.alive > 0 ? csv_field(static_cast<double>(r.groups.alive_members) / r.groups.alive) : CsvField{};
     }},
    // Global relaxation (beyond the thesis): the solve's time, empty when none ran.
    {"t_relax_ms",
     [](const IterationRow& r) { return r.step.relaxed ? csv_field(r.step.timings.relax_ms) : CsvField{}; }},
};

// One RltPoint as landmarks.csv sees it; coordinates whenever it has a global position, even
// when merged or flagged dynamic (then it is not on the map).
struct LandmarkRow {
  const RltPoint& point;
  const RltMapper& mapper;
  const LandmarkScore& score;
  const MapFrameGauge& gauge;
};

CsvField coordinate(const LandmarkRow& r, int axis) {
  return r.point.has_global ? csv_field(r.gauge.point(r.point.global)[axis]) : CsvField{};
}

const Columns<LandmarkRow> kLandmarkColumns = {
    {"id", [](const LandmarkRow& r) { return csv_field(r.point.id); }},
    {"x", [](const LandmarkRow& r) { return coordinate(r, 0); }},
    {"y", [](const LandmarkRow& r) { return coordinate(r, 1); }},
    {"z", [](const LandmarkRow& r) { return coordinate(r, 2); }},
    {"true_id", [](const LandmarkRow& r) { return csv_field(r.score.true_id); }},
    {"error", [](const LandmarkRow& r) { return csv_field(r.score.error); }},
    {"level", [](const LandmarkRow& r) { return csv_field(level_of(r.point, r.mapper)); }},
    {"observations", [](const LandmarkRow& r) { return csv_field(r.point.interval.total()); }},
    {"first_iteration", [](const LandmarkRow& r) { return csv_field(r.point.interval.first()); }},
    {"last_iteration", [](const LandmarkRow& r) { return csv_field(r.point.interval.last()); }},
    {"owner_group", [](const LandmarkRow& r) { return r.point.owner >= 0 ? csv_field(r.point.owner) : CsvField{}; }},
    {"dynamic_flagged", [](const LandmarkRow& r) { return csv_field(r.point.dynamic); }},
    {"true_dynamic", [](const LandmarkRow& r) { return csv_field(r.score.true_dynamic); }},
    {"merged_into", [](const LandmarkRow& r) { return r.point.merged ? csv_field(r.point.merged_into) : CsvField{}; }},
};

class RelativePoint final : public Algorithm {
 public:
  explicit RelativePoint(const point::PointSlamOptions& options) : mapper_(options, relax::solve_relaxation) {}

  const std::string& name() const override { return name_; }
  void step(const ObservationFrame& observation, const TruthFrame& truth) override {
    last_ = mapper_.step(observation);
    gauge_.observe(observation.iteration, mapper_.first_iteration(), truth);
    lost_.add(unregistered_origin(last_.pose_source));
  }
  std::size_t steps_before_map_frame() const override { return gauge_.steps_before(); }

  Rigid3 pose() const override { return gauge_.pose(last_.world_T_robot); }
  const std::vector<int>& assignment() const override { return last_.assignment; }
  const std::vector<int>& changed() const override { return last_.changed; }
  std::optional<Eigen::Vector3d> position(int id) const override {
    const RltPoint& p = mapper_.points()[id];
    if (!p.on_map()) return std::nullopt;
    return gauge_.point(p.global);
  }
  std::vector<int> map_ids() const override {
    std::vector<int> ids;
    for (const RltPoint& p : mapper_.points())
      if (p.on_map()) ids.push_back(p.id);
    return ids;
  }
  std::string failure() const override { return mapper_.failure(); }
  std::string lost() const override { return lost_.reason(); }

  std::vector<std::string> iteration_columns() const override { return column_names(kIterationColumns); }
  void iteration_fields(std::vector<CsvField>& out) const override {
    const point::GroupStats groups = mapper_.group_stats();
    append_fields(kIterationColumns, {last_, groups, mapper_.points().size()}, out);
  }
  std::vector<std::string> landmark_columns() const override { return column_names(kLandmarkColumns); }
  void landmark_rows(const std::function<LandmarkScore(int)>& score,
                     const std::function<void(const std::vector<CsvField>&)>& row) const override {
    std::vector<CsvField> fields;
    for (const RltPoint& p : mapper_.points()) {
      const LandmarkScore s = score(p.id);
      fields.clear();
      append_fields(kLandmarkColumns, {p, mapper_, s, gauge_}, fields);
      row(fields);
    }
  }

 private:
  std::string name_ = "relative_point";
  RltMapper mapper_;
  point::StepResult last_;
  MapFrameGauge gauge_;
  LostPoseCount lost_;
};

}  // namespace

std::unique_ptr<Algorithm> make_relative_point(const point::PointSlamOptions& options) {
  return std::make_unique<RelativePoint>(options);
}

}  // namespace relslam::eval
