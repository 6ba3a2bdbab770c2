// The Relative Plane algorithm (libslam's RltXPointsS, thesis Chapter 4) as an algorithm of a
// planar run: its structure counts and the Profiler's part timings (thesis 4.4.2.5) as
// iterations.csv columns, each RltPlane's observations and group in planes.csv, and its groups
// and links as groups.csv and links.csv, every roll-back
// (Rules 31–34) as rollbacks.csv and their counts in summary.csv; with key points also edges.csv
// and E02's pairs.csv / pair_sigma.csv.
#include "relative_plane.hpp"

#include "key_point_pair_diagnostic.hpp"
#include "pose_prediction.hpp"
#include "relslam/eval/algorithms/columns.hpp"
#include "relslam/plane/rlt_xpoints_s.hpp"

#include <algorithm>
#include <iterator>
#include <numbers>

namespace relslam::eval {
namespace {

using plane::RelativePlaneStep;
using plane::RltXPointsS;

CsvField id_field(int id) { return id >= 0 ? csv_field(id) : CsvField{}; }

struct IterationRow {
  const RelativePlaneStep& step;
  const RltXPointsS& slam;
};

// A field of the active motion model's sample at this iteration; empty without one.
CsvField mm_field(const IterationRow& r, auto value) {
  const plane::MotionModelSample* s = r.step.motion_model != nullptr ? r.step.motion_model->last() : nullptr;
  return s != nullptr && s->iteration == r.step.iteration ? csv_field(value(*s)) : CsvField{};
}

// A field of the active motion model itself; empty without one.
CsvField mm_extent(const IterationRow& r, auto value) {
  return r.step.motion_model != nullptr ? csv_field(value(*r.step.motion_model)) : CsvField{};
}

const Columns<IterationRow> kIterationColumns = {
    {"pose_valid", [](const IterationRow& r) { return csv_field(r.step.pose_valid); }},
    {"rlt_planes", [](const IterationRow& r) { return csv_field(r.slam.planes().size()); }},
    {"groups", [](const IterationRow& r) { return csv_field(r.slam.xpoints().size()); }},
    {"links", [](const IterationRow& r) { return csv_field(r.slam.links().size()); }},
    {"current_group", [](const IterationRow& r) { return id_field(r.step.current_group); }},
    {"global_matches", [](const IterationRow& r) { return csv_field(r.step.global_matches); }},
    {"local_matches", [](const IterationRow& r) { return csv_field(r.step.local_matches); }},
    {"new_planes", [](const IterationRow& r) { return csv_field(r.step.new_planes); }},
    {"pose_planes", [](const IterationRow& r) { return csv_field(r.step.pose_planes); }},
    // Rule 37: one-way (charting-only) links added this iteration.
    {"oneway_links", [](const IterationRow& r) { return csv_field(r.step.oneway_links); }},
    {"unassigned", [](const IterationRow& r) { return csv_field(r.slam.unassigned().size()); }},
    {"t_add_ms", [](const IterationRow& r) { return csv_field(r.step.timings.add_ms); }},
    {"t_manage_ms", [](const IterationRow& r) { return csv_field(r.step.timings.manage_ms); }},
    {"t_compute_ms", [](const IterationRow& r) { return csv_field(r.step.timings.compute_ms); }},
    {"t_build_ms", [](const IterationRow& r) { return csv_field(r.step.timings.build_ms); }},
    {"t_pose_ms", [](const IterationRow& r) { return csv_field(r.step.timings.pose_ms); }},
    // Rules 31–34: this step's hints and roll-backs, and the time restoring and replaying took.
    {"hints", [](const IterationRow& r) { return csv_field(r.step.roll_back.hints); }},
    {"rollbacks", [](const IterationRow& r) { return csv_field(r.step.roll_back.rollbacks); }},
    {"rollbacks_refused", [](const IterationRow& r) { return csv_field(r.step.roll_back.refused); }},
    {"replayed_iterations", [](const IterationRow& r) { return csv_field(r.step.roll_back.replayed_iterations); }},
    {"t_rollback_ms", [](const IterationRow& r) { return csv_field(r.step.timings.roll_back_ms); }},
    // The motion model (Rules 23–27, thesis 4.3.6): the tracked robot in its frame.
    {"mm_active", [](const IterationRow& r) { return csv_field(r.step.motion_model != nullptr); }},
    {"mm_distance", [](const IterationRow& r) { return mm_field(r, [](const auto& s) { return s.distance; }); }},
    {"mm_delta_normal",
     [](const IterationRow& r) { return mm_field(r, [](const auto& s) { return s.delta_normal; }); }},
    {"mm_delta_tangent",
     [](const IterationRow& r) { return mm_field(r, [](const auto& s) { return s.delta_tangent; }); }},
    {"mm_heading_deg", [](const IterationRow& r) {
       return mm_field(r, [](const auto& s) { return s.mm_T_robot.heading * 180.0 / std::numbers::pi; });
     }},
    // The one plane it tracks and its extent along the plane's tangent from the plane's map
    // midpoint at the start (thesis 4.3.6 [s_min, s_max]; Rule 23 only ever widens it).
    {"mm_plane", [](const IterationRow& r) { return mm_extent(r, [](const auto& m) { return m.plane(); }); }},
    {"mm_s_min", [](const IterationRow& r) { return mm_extent(r, [](const auto& m) { return m.s_min(); }); }},
    {"mm_s_max", [](const IterationRow& r) { return mm_extent(r, [](const auto& m) { return m.s_max(); }); }},
};

// The adaptive preset's: why the pose is (in)valid this iteration (pose_integrity.hpp). Not a
// column under the thesis preset, whose runs keep their files.
const Columns<IterationRow> kIntegrityColumns = {
    {"pose_reason", [](const IterationRow& r) { return csv_field(std::string(to_string(r.step.pose_reason))); }},
};

// With a motion prediction: the step predicted from the previous frame's pose and the wall
// registration's pairs and residual (motion_prediction.*). Not a column without one.
struct PredictionRow {
  const PosePrediction& prediction;
};

const Columns<PredictionRow> kPredictionColumns = {
    {"pred_step_x", [](const PredictionRow& r) { return csv_field(r.prediction.step().translation.x()); }},
    {"pred_step_z", [](const PredictionRow& r) { return csv_field(r.prediction.step().translation.y()); }},
    {"pred_step_heading_deg",
     [](const PredictionRow& r) { return csv_field(r.prediction.step().heading * 180.0 / std::numbers::pi); }},
    {"reg_pairs", [](const PredictionRow& r) { return csv_field(r.prediction.registration().pairs); }},
    {"reg_rms", [](const PredictionRow& r) {
       return r.prediction.registration().used ? csv_field(r.prediction.registration().rms) : CsvField{};
     }},
};

// With motion_prediction.report_prediction: whose pose the frame reports (algorithm, prediction).
const Columns<PredictionRow> kSourceColumns = {
    {"pose_source", [](const PredictionRow& r) { return csv_field(std::string(to_string(r.prediction.source()))); }},
};

bool adaptive(const RltXPointsS& slam) { return slam.options().preset == plane::Preset::Adaptive; }

// One RltPlane as planes.csv sees it, after the recorder's scored columns.
struct PlaneRow {
  const plane::RltPlane& plane;
  const plane::MapPlane& mapped;
};

const Columns<PlaneRow> kPlaneColumns = {
    {"n_obs", [](const PlaneRow& r) { return csv_field(r.plane.readings()); }},
    {"group", [](const PlaneRow& r) { return id_field(r.mapped.source); }},
    {"memberships", [](const PlaneRow& r) { return csv_field(r.plane.refs().size()); }},
    {"first_iteration", [](const PlaneRow& r) { return csv_field(r.plane.created_iteration()); }},
    {"last_iteration", [](const PlaneRow& r) { return csv_field(r.plane.last_iteration()); }},
};

// Ids joined by ';' (groups.csv's planes, links.csv's linking planes).
std::string joined(const std::vector<int>& ids) {
  std::string out;
  for (int id : ids) out += (out.empty() ? "" : ";") + std::to_string(id);
  return out;
}

class RelativePlane final : public PlaneAlgorithm {
 public:
  RelativePlane(const plane::RelativePlaneOptions& options, const MotionPredictionOptions& prediction,
                const PlanarPose& world_T_start)
      : slam_(options, world_T_start), report_prediction_(prediction.report_prediction) {
    if (prediction.enabled()) prediction_.emplace(prediction, world_T_start);
  }

  const std::string& name() const override { return name_; }

  void step(const PlaneFrame& frame) override {
    if (!prediction_) {
      last_ = slam_.step(frame);
      pose_ = last_.pose_valid ? std::optional<PlanarPose>(last_.world_T_robot) : std::nullopt;
      return;
    }
    last_ = slam_.step(prediction_->moved(frame));
    pose_ = prediction_->robot_pose(last_.pose_valid ? std::optional<PlanarPose>(last_.world_T_robot) : std::nullopt);
  }

  void read_out() override {
    totals_.hints += last_.roll_back.hints;
    totals_.rollbacks += last_.roll_back.rollbacks;
    totals_.refused += last_.roll_back.refused;
    totals_.replayed_iterations += last_.roll_back.replayed_iterations;
    assignment_.assign(last_.assignment.begin(), last_.assignment.end());
    map_.clear();
    for (std::size_t id = 0; id < last_.map.size(); ++id)
      if (last_.map[id].mapped) map_.emplace_back(static_cast<int>(id), last_.map[id].plane);
  }

  std::optional<PlanarPose> pose() const override {
    return pose_;
  }
  const std::vector<int>& assignment() const override { return assignment_; }
  const std::vector<MappedPlane>& map() const override { return map_; }
  std::vector<PlaneGroup> groups() const override {
    std::vector<PlaneGroup> out;
    for (const plane::RltXPoint& x : slam_.xpoints())
      if (x.placed()) out.push_back({x.id(), x.world_pose(), {x.planes().begin(), x.planes().end()}});
    return out;
  }

  std::vector<std::string> iteration_columns() const override {
    std::vector<std::string> names = column_names(kIterationColumns);
    if (adaptive(slam_)) std::ranges::copy(column_names(kIntegrityColumns), std::back_inserter(names));
    if (prediction_) std::ranges::copy(column_names(kPredictionColumns), std::back_inserter(names));
    if (reports_source()) std::ranges::copy(column_names(kSourceColumns), std::back_inserter(names));
    return names;
  }
  void iteration_fields(std::vector<CsvField>& out) const override {
    append_fields(kIterationColumns, IterationRow{last_, slam_}, out);
    if (adaptive(slam_)) append_fields(kIntegrityColumns, IterationRow{last_, slam_}, out);
    if (prediction_) append_fields(kPredictionColumns, PredictionRow{*prediction_}, out);
    if (reports_source()) append_fields(kSourceColumns, PredictionRow{*prediction_}, out);
  }
  bool scores_wrong_valid() const override { return adaptive(slam_); }
  std::vector<std::string> plane_columns() const override { return column_names(kPlaneColumns); }
  void plane_fields(int id, std::vector<CsvField>& out) const override {
    const auto i = static_cast<std::size_t>(id);
    append_fields(kPlaneColumns, PlaneRow{slam_.planes().at(i), slam_.map().at(i)}, out);
  }

  bool claims_key_points() const override { return slam_.options().key_points; }
  std::vector<KeyPointClaim> key_point_claims() const override {
    // Each observed plane's memberships with a key point valid at this iteration: what Rule 16
    // grows a partial observation from (thesis 4.4.3.11). A motion model's membership is not one: the
    // end it holds is the track's as a whole (Rule 23), in a given view it can be the frustum's
    // cut, and the pose takes no key point from it (RltXPointRef::tracked).
    std::vector<KeyPointClaim> out;
    for (std::size_t i = 0; i < last_.assignment.size(); ++i) {
      const plane::RltPlane& p = slam_.planes().at(static_cast<std::size_t>(last_.assignment[i]));
      for (const plane::RltXPointRef& ref : p.refs()) {
        if (!ref.valid || ref.tracked || !ref.interval.in_interval(last_.iteration)) continue;
        if (ref.key_point == plane::KeyPoint::None) continue;
        out.push_back({static_cast<int>(i), ref.xpoint, p.id(), static_cast<int>(ref.key_point), ref.size_static,
                       ambiguous_in(ref.xpoint, p.id()), ref.interval.start, ref.interval.end});
      }
    }
    return out;
  }

  void write_tables(const std::filesystem::path& dir) const override {
    CsvWriter groups(dir / "groups.csv", {"group_id", "created_iter", "placed", "global_x", "global_z",
                                          "global_psi_deg", "planes", "base_plane", "adjacent"});
    for (const plane::RltXPoint& x : slam_.xpoints()) {
      const PlanarPose& p = x.world_pose();
      groups.row(x.id(), x.created_iteration(), x.placed(), p.translation.x(), p.translation.y(),
                 p.heading * 180.0 / std::numbers::pi, joined(x.planes()),
                 x.planes().empty() ? CsvField{} : csv_field(x.planes().front()), joined(x.adjacent()));
    }
    groups.close();
    CsvWriter links(dir / "links.csv", {"from", "to", "linking_planes", "created_iter", "first"});
    for (const plane::RltXPointLink& l : slam_.links())
      links.row(id_field(l.from), id_field(l.to), joined(l.planes), l.created_iteration, l.first);
    links.close();
    write_edges(dir / "edges.csv");
    write_roll_backs(dir / "rollbacks.csv");
    // E02 (Fig 68): Rule 13's four offset series of one growing/shrinking pair, with key points only.
    if (slam_.options().key_points) write_key_point_pair_diagnostic(dir, slam_.planes(), slam_.options());
  }

 private:
  // edges.csv (diagnostic): each group's last comparison of every chain edge — the piece
  // it used, both planes' lengths there and their canonical sizes in the group (Rule 28's L_e vs
  // L*, Fig 87), key points, static flags, the Rule 15 tie, the offset and the chosen pair's σ.
  void write_edges(const std::filesystem::path& path) const {
    CsvWriter edges(path, {"group", "plane1", "plane2", "valid", "interval_start", "interval_end", "samples",
                           "length1", "length2", "canonical1", "canonical2", "kp1", "kp2", "static1", "static2",
                           "ambiguous", "dx", "dz", "dpsi_deg", "sigma"});
    for (const plane::RltXPoint& x : slam_.xpoints())
      for (std::size_t e = 0; e < x.edges().size(); ++e) {
        const plane::CompareResult& c = x.edges()[e];
        const plane::RltXPointRef* r1 = slam_.planes().at(static_cast<std::size_t>(x.planes()[e])).ref(x.id());
        const plane::RltXPointRef* r2 = slam_.planes().at(static_cast<std::size_t>(x.planes()[e + 1])).ref(x.id());
        edges.row(x.id(), x.planes()[e], x.planes()[e + 1], c.valid, c.interval.start, c.interval.end, c.samples,
                  c.length1, c.length2, r1->max_length, r2->max_length, static_cast<int>(c.key_point1),
                  static_cast<int>(c.key_point2), c.static1, c.static2, c.ambiguous, c.delta.translation.x(),
                  c.delta.translation.y(), c.delta.heading * 180.0 / std::numbers::pi, c.sigma);
      }
    edges.close();
  }

  // rollbacks.csv: every roll-back request (Rules 33, 34), the plane, group and hint
  // level that set it off (empty for a forced one), how many iterations it replayed, and whether
  // it was served (too_old, nesting: refused).
  void write_roll_backs(const std::filesystem::path& path) const {
    CsvWriter out(path, {"iteration_requested", "target_iteration", "plane", "group", "level", "replayed_iterations",
                         "outcome"});
    for (const plane::RollBackEvent& e : slam_.roll_back_log())
      out.row(e.iteration_requested, e.target_iteration, id_field(e.plane), id_field(e.xpoint),
              e.level > 0 ? csv_field(e.level) : CsvField{}, e.replayed_iterations, std::string(to_string(e.outcome)));
    out.close();
  }

 public:
  std::vector<std::string> summary_columns() const override {
    return {"hints", "rollbacks", "rollbacks_refused", "replayed_iterations"};
  }
  void summary_fields(std::vector<CsvField>& out) const override {
    out.insert(out.end(), {csv_field(totals_.hints), csv_field(totals_.rollbacks), csv_field(totals_.refused),
                           csv_field(totals_.replayed_iterations)});
  }

 private:
  bool reports_source() const { return prediction_ && report_prediction_; }

  // Whether one of the chain edges of group x that compare `plane` tied both diagonals (Rule 15).
  bool ambiguous_in(int x, int plane) const {
    const plane::RltXPoint& group = slam_.xpoints().at(static_cast<std::size_t>(x));
    const std::vector<int>& chain = group.planes();
    for (std::size_t e = 0; e < group.edges().size(); ++e)
      if ((chain[e] == plane || chain[e + 1] == plane) && group.edges()[e].ambiguous) return true;
    return false;
  }

  std::string name_ = "relative_plane";
  RltXPointsS slam_;
  RelativePlaneStep last_;
  bool report_prediction_ = false;            // motion_prediction.report_prediction
  std::optional<PosePrediction> prediction_;  // motion_prediction.*: none for the thesis
  std::optional<PlanarPose> pose_;            // the robot's, after the prediction is composed back
  plane::RollBackCounts totals_;  // Rules 31–34 over the run (summary.csv)
  std::vector<int> assignment_;
  std::vector<MappedPlane> map_;
};

}  // namespace

std::unique_ptr<PlaneAlgorithm> make_relative_plane(const plane::RelativePlaneOptions& options,
                                                    const MotionPredictionOptions& prediction,
                                                    const PlanarPose& world_T_start) {
  return std::make_unique<RelativePlane>(options, prediction, world_T_start);
}

}  // namespace relslam::eval
