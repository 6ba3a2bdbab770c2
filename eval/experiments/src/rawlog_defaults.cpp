#include "relslam/eval/experiments/rawlog_defaults.hpp"

#include <algorithm>
#include <sstream>

namespace relslam::eval {
namespace {

bool lists(const Scenario& s, const std::string& name) {
  return std::find(s.algorithms.begin(), s.algorithms.end(), name) != s.algorithms.end();
}

// The noise-derived bound at `key`, capped at half the landmarks' spacing unless given.
void cap_bound(LoadedScenario& adapted, const std::string& key, double& bound, double cap, nlohmann::json& record) {
  if (adapted.origins.contains(key) || bound <= cap) return;
  bound = cap;
  std::ostringstream why;
  why << "planar log: half the median distance between neighbouring points of a frame (" << 2 * cap << ")";
  adapted.scenario.derived[key] = {bound, why.str()};
  record[key] = {{"value", bound}, {"source", why.str()}};
}

}  // namespace

std::string default_rawlog_algorithms(const RawlogFiles& files) {
  // The log alone: the truth files are read, and checked, when the run starts.
  return shape_of(read_rawlog(files.rawlog)).planar ? "relative_point,ekf2d" : "relative_point,ekf6d";
}

std::vector<std::string> default_rawlog_settings(const RawlogFiles& files) {
  const Rawlog log = read_rawlog(files.rawlog);
  // A log of 2-D laser scans only: its walls through Relative Plane, sized as for scenarios/
  // real-sena.json (docs/laser-scans.md): real steps and flickering walls.
  if (log.frames.empty())
    return {"kind=planar",
            "algorithms=relative_plane,wall_odometry",
            "motion_prediction.register_walls=true",
            "motion_prediction.constant_velocity=true",
            "relative_plane.key_points=true",
            "relative_plane.open_cut_ends=true",
            "relative_plane.min_readings=2",
            "relative_plane.min_common=2",
            "relative_plane.local_match.max_offset_change=1.0",
            "relative_plane.local_match.box_margin=1.0",
            "relative_plane.rules.two_linking_planes=false"};
  return {std::string("algorithms=") + (shape_of(log).planar ? "relative_point,ekf2d" : "relative_point,ekf6d")};
}

LoadedScenario with_rawlog_shape(const LoadedScenario& loaded, const RawlogSource& source, nlohmann::json& record) {
  const RawlogShape& shape = source.shape();
  LoadedScenario adapted = loaded;
  Scenario& s = adapted.scenario;
  if (!shape.planar) {
    for (const char* planar_only : {"ekf2d", "ekf2d_no_odometry"})
      if (lists(s, planar_only))
        throw loaded.error("algorithms", std::string(planar_only) + " is MRPT's planar filter and this log is " +
                                             shape.why + "; use ekf6d");
    return adapted;
  }
  const auto given = [&](const std::string& key) { return loaded.origins.contains(key); };
  // A planar log that carries odometry in most frames: both estimators take it. Without it the
  // EKF's constant-position prediction cannot follow turns of tens of degrees per frame (MRPT's
  // kf-slam_demo: ekf2d ends tens of metres off, every step a re-initialisation).
  if (2 * shape.frames_with_odometry >= shape.frames) {
    const std::string why = "planar log with odometry in " + std::to_string(shape.frames_with_odometry) + " of " +
                            std::to_string(shape.frames) + " frames";
    if (!given("relative_point.use_odometry")) {
      s.relative_point.use_odometry = true;
      record["relative_point.use_odometry"] = {{"value", true},
                                               {"source", why + ": dead reckoning bridges, as at Victoria Park"}};
    }
    if (!given("ekf2d.use_odometry")) {
      s.ekf2d.use_odometry = true;
      record["ekf2d.use_odometry"] = {{"value", true}, {"source", why + ": the filter's prediction step"}};
    }
  }
  if (s.relative_point.preset == point::Preset::Adaptive && shape.point_spacing > 0) {
    const double cap = shape.point_spacing / 2;
    cap_bound(adapted, "relative_point.global_bound", s.relative_point.global_bound, cap, record);
    cap_bound(adapted, "relative_point.merge_bound", s.relative_point.merge_bound, cap, record);
  }
  if (!given("ekf2d.association") && source.ids_everywhere()) {
    s.ekf2d.association = EkfAssociation::Known;
    record["ekf2d.association"] = {{"value", "known"}, {"source", "every measurement carries its landmark id"}};
  }
  return adapted;
}

}  // namespace relslam::eval
