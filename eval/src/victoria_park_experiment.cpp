#include "relslam/eval/victoria_park_experiment.hpp"

#include "algorithm_set.hpp"
#include "relslam/eval/ackermann.hpp"
#include "relslam/eval/csv_writer.hpp"
#include "relslam/eval/progress.hpp"
#include "relslam/eval/range_bearing.hpp"
#include "relslam/eval/tum_writer.hpp"

#include <algorithm>
#include <chrono>
#include <numbers>
#include <cstdio>
#include <optional>

namespace relslam::eval {
namespace {

// A GPS fix at time t, linearly interpolated between the fixes around it when both are within
// `max_gap` seconds (the receiver drops out under trees) [C: 1 s].
std::optional<Eigen::Vector2d> gps_at(const std::vector<GpsFix>& gps, double t, double max_gap = 1.0) {
  auto after = std::lower_bound(gps.begin(), gps.end(), t, [](const GpsFix& f, double time) { return f.time < time; });
  if (after == gps.end() || after == gps.begin()) return std::nullopt;
  const GpsFix& before = *(after - 1);
  if (t - before.time > max_gap || after->time - t > max_gap) return std::nullopt;
  const double w = (t - before.time) / (after->time - before.time);
  return (1 - w) * before.position + w * after->position;
}

Eigen::Vector2d planar(const Eigen::Vector3d& p_ours) {
  const Eigen::Vector3d m = mrpt_from_robot(p_ours);
  return {m.x(), m.y()};
}

void write_gps_files(const std::filesystem::path& out, const AlgorithmRun& run, const std::vector<std::optional<Eigen::Vector2d>>& gps,
                     GpsComparison& comparison) {
  const std::vector<Rigid3>& trajectory = run.trajectory();
  std::vector<Eigen::Vector2d> from, to;
  for (std::size_t k = 0; k < trajectory.size() && k < gps.size(); ++k)
    if (gps[k]) {
      from.push_back(planar(trajectory[k].translation));
      to.push_back(*gps[k]);
    }
  comparison.algorithm = run.name();
  comparison.scans = static_cast<int>(trajectory.size());
  comparison.alignment = align_planar(from, to, false);
  const PlanarAlignment& a = comparison.alignment;
  CsvWriter path(out / run.name() / "trajectory_gps_frame.csv", {"iteration", "x", "y", "gps_x", "gps_y"});
  for (std::size_t k = 0; k < trajectory.size(); ++k) {
    const Eigen::Vector2d p = a.apply(planar(trajectory[k].translation));
    const bool fix = k < gps.size() && gps[k].has_value();
    path.row(k, p.x(), p.y(), fix ? std::optional(gps[k]->x()) : std::nullopt, fix ? std::optional(gps[k]->y()) : std::nullopt);
  }
  path.close();
  CsvWriter landmarks(out / run.name() / "landmarks_gps_frame.csv", {"x", "y"});
  for (const Eigen::Vector3d& l : run.map()) {
    const Eigen::Vector2d p = a.apply(planar(l));
    landmarks.row(p.x(), p.y());
  }
  landmarks.close();
}

}  // namespace

VictoriaParkStream::VictoriaParkStream(const VictoriaParkLog& log, const Scenario& scenario)
    : filter_(scenario.victoria_park.filter), dead_reckoning_(log.inputs) {
  // The laser's range and field of view, for the EKF's gating (spec mrpt §0.5).
  sensor_.min_range = filter_.min_range;
  sensor_.max_range = std::min(filter_.max_range, 81.91);  // 13-bit centimetre ranges
  sensor_.field_of_view_yaw_rad = std::numbers::pi;        // 0..180 degrees
  sensor_.std_range = scenario.ekf2d.std_range;
  sensor_.std_yaw_rad = scenario.ekf2d.std_yaw_rad;
}

std::optional<Pose2> VictoriaParkStream::motion(const std::vector<LaserScan>& scans, std::size_t i) const {
  if (i == 0) return std::nullopt;
  return dead_reckoning_.motion(scans[i - 1].time, scans[i].time);
}

ObservationFrame VictoriaParkStream::frame(const std::vector<LaserScan>& scans, std::size_t i) const {
  ObservationFrame frame;
  frame.iteration = static_cast<int>(i);
  for (const TreeDetection& tree : scans[i].trees)
    if (filter_.keeps(tree)) {
      const Eigen::Vector2d p = laser_point(tree);
      frame.points.push_back(robot_from_mrpt({p.x(), p.y(), 0.0}));
    }
  if (const auto m = motion(scans, i)) frame.odometry = robot_pose_from_planar(*m);
  return frame;
}

VictoriaParkResult run_victoria_park(const LoadedScenario& loaded, const VictoriaParkLog& log,
                                     const std::filesystem::path& out, bool progress) {
  const Scenario& scenario = loaded.scenario;
  if (scenario.kind != ScenarioKind::VictoriaPark)
    throw loaded.error("kind", "relslam victoria-park needs a scenario of kind victoria_park (scenarios/victoria-park.json)");
  if (scenario.algorithms.empty())
    throw loaded.error("algorithms", "the scenario lists no algorithm to run; add one, e.g. --set algorithms=relative_point");
  const std::vector<LaserScan> scans =
      scans_in(log, parse_scan_window(scenario.victoria_park.window, "victoria_park.window"), "victoria_park.window");
  const VictoriaParkStream stream(log, scenario);

  VictoriaParkResult result;
  const auto start = std::chrono::steady_clock::now();
  LandmarkTruth truth;
  truth.known = false;
  AlgorithmSet algorithms(scenario, truth, stream.sensor(), out);
  CsvWriter table(out / "scans.csv", {"iteration", "scan", "time", "trees", "kept", "odometry_x", "odometry_y",
                                      "odometry_heading", "gps_x", "gps_y"});
  TumWriter gps_tum(out / "gps.tum");
  std::vector<std::optional<Eigen::Vector2d>> gps;
  Progress bar("victoria park " + scenario.victoria_park.window, static_cast<long long>(scans.size()), progress);
  for (std::size_t i = 0; i < scans.size(); ++i) {
    const int k = static_cast<int>(i);
    const ObservationFrame frame = stream.frame(scans, i);
    const std::optional<Pose2> motion = stream.motion(scans, i);
    TruthFrame t;
    t.iteration = k;
    t.pose_known = false;
    t.landmark_ids.assign(frame.points.size(), -1);
    algorithms.step(frame, t);

    gps.push_back(gps_at(log.gps, scans[i].time));
    result.gps_scans += gps.back().has_value();
    result.scans_below_three += frame.points.size() < 3;
    if (gps.back()) gps_tum.write(k, {Eigen::Matrix3d::Identity(), {gps.back()->x(), gps.back()->y(), 0.0}});
    table.row(k, scans[i].index, scans[i].time, scans[i].trees.size(), frame.points.size(),
              motion ? std::optional(motion->x) : std::nullopt, motion ? std::optional(motion->y) : std::nullopt,
              motion ? std::optional(motion->heading) : std::nullopt, gps.back() ? std::optional(gps.back()->x()) : std::nullopt,
              gps.back() ? std::optional(gps.back()->y()) : std::nullopt);
    bar.update(k + 1);
  }
  table.close();
  gps_tum.close();
  algorithms.finish(result.experiment);
  bar.finish();
  result.scans = static_cast<int>(scans.size());

  // Against GPS (positions only, after the best rigid 2D alignment) and against the map of the
  // EKF with odometry, the best-informed estimate here.
  CsvWriter gps_table(out / "gps_comparison.csv",
                      {"algorithm", "scans", "gps_pairs", "ate_rmse", "ate_max", "rotation_deg", "tx", "ty"});
  const AlgorithmRun* reference = nullptr;
  PlanarAlignment reference_to_gps;
  for (const auto& run : algorithms.runs()) {
    GpsComparison c;
    write_gps_files(out, *run, gps, c);
    const PlanarAlignment& a = c.alignment;
    gps_table.row(c.algorithm, c.scans, a.pairs, a.pairs ? std::optional(a.rmse) : std::nullopt,
                  a.pairs ? std::optional(a.max) : std::nullopt, a.rotation_deg(), a.translation.x(), a.translation.y());
    result.gps.push_back(c);
    if (run->name() == "ekf2d") {
      reference = run.get();
      reference_to_gps = c.alignment;
    }
  }
  gps_table.close();
  if (reference) {
    std::vector<Eigen::Vector2d> reference_map;
    for (const Eigen::Vector3d& l : reference->map()) reference_map.push_back(planar(l));
    CsvWriter maps(out / "map_comparison.csv", {"algorithm", "reference", "landmarks", "reference_landmarks", "matched",
                                                "rms", "median", "scale", "rotation_deg"});
    for (const auto& run : algorithms.runs()) {
      if (run.get() == reference) continue;
      std::vector<Eigen::Vector2d> map;
      for (const Eigen::Vector3d& l : run->map()) map.push_back(planar(l));
      // A tree matches within 5 m: above the maps' disagreement, below the trees' usual spacing [C].
      const MapComparison m = compare_maps(map, reference_map, 5.0);
      // The map as stretched over the reference (thesis Figs 164, 166), shown in the GPS frame.
      CsvWriter fitted(out / run->name() / "landmarks_similarity_fit.csv", {"x", "y"});
      for (const Eigen::Vector2d& l : map) {
        const Eigen::Vector2d p = reference_to_gps.apply(m.alignment.apply(l));
        fitted.row(p.x(), p.y());
      }
      fitted.close();
      maps.row(run->name(), reference->name(), m.landmarks, m.reference_landmarks, m.matched, m.rms, m.median,
               m.alignment.scale, m.alignment.rotation_deg());
      result.maps.emplace_back(run->name(), m);
    }
    maps.close();
  }
  result.experiment.iterations = result.scans;
  result.experiment.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.experiment.source = {{"victoria_park",
                               {{"window", scenario.victoria_park.window},
                                {"first_scan", scans.empty() ? 0 : scans.front().index},
                                {"last_scan", scans.empty() ? 0 : scans.back().index},
                                {"first_time", scans.empty() ? 0.0 : scans.front().time},
                                {"last_time", scans.empty() ? 0.0 : scans.back().time},
                                {"scans", result.scans},
                                {"scans_below_three_trees", result.scans_below_three},
                                {"scans_with_gps", result.gps_scans}}}};
  return result;
}

void print_victoria_park(const VictoriaParkResult& r, const std::string& title) {
  std::printf("%s: %d scans, %d with fewer than 3 trees, %d with GPS\n", title.c_str(), r.scans, r.scans_below_three,
              r.gps_scans);
  std::printf("%-20s %-8s %8s %10s %12s %10s %10s\n", "algorithm", "status", "scans", "map size", "ATE vs GPS", "median ms",
              "max ms");
  for (std::size_t i = 0; i < r.experiment.rows.size(); ++i) {
    const SummaryRow& s = r.experiment.rows[i];
    const PlanarAlignment& a = r.gps[i].alignment;
    std::printf("%-20s %-8s %8d %10d %12.3g %10.4g %10.4g\n", s.algorithm.c_str(), s.status.substr(0, s.status.find(' ')).c_str(),
                s.iterations, s.landmarks_on_map, a.pairs ? a.rmse : std::nan(""), s.runtime.median_ms, s.runtime.max_ms);
  }
  for (const auto& [name, m] : r.maps)
    std::printf("%s map vs ekf2d: %d of %d landmarks matched within 5 m, rms %.2f m, median %.2f m, scale %.3f\n",
                name.c_str(), m.matched, m.landmarks, m.rms, m.median, m.alignment.scale);
  for (const SummaryRow& s : r.experiment.rows)
    if (s.status != "ok") std::printf("%s: %s\n", s.algorithm.c_str(), s.status.c_str());
}

}  // namespace relslam::eval
