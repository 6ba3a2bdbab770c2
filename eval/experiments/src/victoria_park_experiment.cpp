#include "relslam/eval/experiments/victoria_park_experiment.hpp"

#include "relslam/eval/experiments/require_algorithms.hpp"
#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/io/range_bearing.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

namespace relslam::eval {
namespace {

Eigen::Vector2d planar(const Eigen::Vector3d& p_ours) {
  const Eigen::Vector3d m = mrpt_from_robot(p_ours);
  return {m.x(), m.y()};
}

void write_gps_files(const std::filesystem::path& out, const AlgorithmRecorder& run,
                     const std::vector<std::optional<Eigen::Vector2d>>& gps, GpsComparison& comparison) {
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
    path.row(k, p.x(), p.y(), fix ? std::optional(gps[k]->x()) : std::nullopt,
             fix ? std::optional(gps[k]->y()) : std::nullopt);
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

VictoriaParkResult run_victoria_park(const LoadedScenario& loaded, const VictoriaParkLog& log,
                                     const std::filesystem::path& out, bool progress) {
  const Scenario& scenario = loaded.scenario;
  if (scenario.kind != ScenarioKind::VictoriaPark)
    throw loaded.error("kind",
                       "relslam victoria-park needs a scenario of kind victoria_park (scenarios/victoria-park.json)");
  require_algorithms(loaded);
  const auto start = std::chrono::steady_clock::now();
  VictoriaParkSource source(log, scenario, out);
  Experiment experiment(loaded, source, out);
  VictoriaParkResult result;
  result.experiment = experiment.run(progress);
  result.scans = source.scans();
  result.gps_scans = source.gps_scans();
  result.scans_below_three = source.scans_below_three();
  const std::vector<std::optional<Eigen::Vector2d>>& gps = source.gps();

  // Against GPS (positions only, after the best rigid 2D alignment) and against the map of the
  // EKF with odometry, the best-informed estimate here.
  CsvWriter gps_table(out / "gps_comparison.csv",
                      {"algorithm", "scans", "gps_pairs", "ate_rmse", "ate_max", "rotation_deg", "tx", "ty"});
  const AlgorithmRecorder* reference = nullptr;
  PlanarAlignment reference_to_gps;
  for (const auto& run : experiment.recorders()) {
    GpsComparison c;
    write_gps_files(out, *run, gps, c);
    const PlanarAlignment& a = c.alignment;
    gps_table.row(c.algorithm, c.scans, a.pairs, a.pairs ? std::optional(a.rmse) : std::nullopt,
                  a.pairs ? std::optional(a.max) : std::nullopt, a.rotation_deg(), a.translation.x(),
                  a.translation.y());
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
    for (const auto& run : experiment.recorders()) {
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
  result.experiment.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

void print_victoria_park(const VictoriaParkResult& r, const std::string& title) {
  std::printf("%s: %d scans, %d with fewer than 3 trees, %d with GPS\n", title.c_str(), r.scans, r.scans_below_three,
              r.gps_scans);
  std::printf("%-20s %-8s %8s %10s %12s %10s %10s\n", "algorithm", "status", "scans", "map size", "ATE vs GPS",
              "median ms", "max ms");
  for (std::size_t i = 0; i < r.experiment.rows.size(); ++i) {
    const SummaryRow& s = r.experiment.rows[i];
    const PlanarAlignment& a = r.gps[i].alignment;
    std::printf("%-20s %-8s %8d %10d %12.3g %10.4g %10.4g\n", s.algorithm.c_str(),
                std::string(to_string(s.status.kind)).c_str(), s.iterations, s.landmarks_on_map,
                a.pairs ? a.rmse : std::nan(""), s.runtime.median_ms, s.runtime.max_ms);
  }
  for (const auto& [name, m] : r.maps)
    std::printf("%s map vs ekf2d: %d of %d landmarks matched within 5 m, rms %.2f m, median %.2f m, scale %.3f\n",
                name.c_str(), m.matched, m.landmarks, m.rms, m.median, m.alignment.scale);
  for (const SummaryRow& s : r.experiment.rows)
    if (!s.status.is_ok()) std::printf("%s: %s\n", s.algorithm.c_str(), s.status.text().c_str());
}

}  // namespace relslam::eval
