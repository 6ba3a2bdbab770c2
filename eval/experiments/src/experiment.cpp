#include "relslam/eval/experiments/experiment.hpp"

#include "relslam/eval/config/point_bounds.hpp"
#include "relslam/eval/experiments/ekf_log_settings.hpp"
#include "relslam/eval/experiments/rawlog_defaults.hpp"
#include "relslam/eval/experiments/require_algorithms.hpp"
#include "relslam/eval/io/run_folder.hpp"
#include "relslam/point/noise_estimate.hpp"
#include "relslam/point/rlt_mapper.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <sstream>

namespace relslam::eval {

namespace {

// Iterations of the pilot run that estimates the noise of a rawlog without a sensor model: a
// few final groups (look-ahead 60) and many temporary ones form in them, hundreds of member
// pairs at sparse densities [C].
constexpr long long kNoisePilotIterations = 300;

// The noise of data that states none, estimated online: pilot runs of Relative Point
// over the first iterations, whose groups' averages show the noise (estimate_noise_online). The
// run itself then starts over with the bounds scaled from it, so that its map never holds what
// too narrow bounds made of noisier data.
NoiseModel estimated_noise(const Scenario& scenario, const RawlogFiles& files) {
  long long seen = 0;
  const std::optional<point::NoiseEstimate> estimate =
      point::estimate_noise_online(scenario.relative_point, [&](point::RltMapper& mapper) {
        RawlogSource source(files);
        seen = 0;
        source.stream([&](const ObservationFrame& observation, const TruthFrame&) {
          if (seen++ < kNoisePilotIterations) mapper.step(observation);
        });
      });
  std::ostringstream text;
  text << "the first " << std::min(seen, kNoisePilotIterations) << " iterations";
  if (!estimate)
    return {0, "thesis bounds: the rawlog gives no sensor noise and " + text.str() + " formed no group to estimate it"};
  std::ostringstream source_text;
  source_text << "online estimate: sigma " << estimate->sigma << " from the spread of " << estimate->pairs
              << " member-pair distances about their group averages (" << estimate->groups << " groups, "
              << text.str() << " of pilot run " << estimate->pilot_runs << ")";
  return {estimate->sigma, source_text.str()};
}

// The adaptive preset's bounds from the rawlog's own sensor model (the scenario's simulator
// noise says nothing about recorded data): the larger of the range noise and the bearing
// noise at the far range; without one, estimated online from a pilot run over `files`.
LoadedScenario with_rawlog_noise(const LoadedScenario& loaded, const RangeBearingSensor& sensor,
                                 const RawlogFiles& files) {
  LoadedScenario adapted = loaded;
  if (adapted.scenario.relative_point.preset != point::Preset::Adaptive) return adapted;
  const double bearing = std::max(sensor.std_yaw_rad, sensor.std_pitch_rad) * sensor.max_range;
  NoiseModel noise{std::max(sensor.std_range, bearing), ""};
  if (noise.sigma > 0) {
    std::ostringstream source;
    source << "rawlog sensor model (std_range " << sensor.std_range << ", bearing std x max_range " << bearing << ")";
    noise.source = source.str();
  } else {
    noise = estimated_noise(loaded.scenario, files);
  }
  derive_point_bounds(adapted.scenario, noise, [&](const std::string& key) { return loaded.origins.contains(key); });
  return adapted;
}

}  // namespace

ExperimentResult run_on_rawlog(const LoadedScenario& loaded, const RawlogFiles& files, const std::filesystem::path& out,
                               bool progress) {
  require_algorithms(loaded);
  RawlogSource source(files);
  nlohmann::json planar_defaults = nlohmann::json::object();
  LoadedScenario adapted = with_rawlog_shape(with_rawlog_noise(loaded, source.sensor(), files), source, planar_defaults);
  // The EKFs' noise from the log unless the scenario sets it, and where each value came from.
  const std::vector<SettingSource> ekf_settings = apply_log_ekf_settings(adapted.scenario, loaded, source.log());
  if (progress && !ekf_settings.empty()) {
    std::printf("EKF settings (source: log, scenario, tuned or default):\n");
    print_settings(ekf_settings);
  }
  const Scenario& scenario = adapted.scenario;
  if (std::find(scenario.algorithms.begin(), scenario.algorithms.end(), "ekf6d") != scenario.algorithms.end() &&
      scenario.ekf6d.association == EkfAssociation::Known && !source.ids_everywhere())
    throw loaded.error("ekf6d.association", "the rawlog does not give every landmark an id; use jcbb or nn");
  source.record_into(out);
  Experiment experiment(adapted, source, out);
  ExperimentResult result = experiment.run(progress);
  if (!adapted.scenario.derived.empty()) result.source["derived"] = derived_json(adapted.scenario);
  if (!planar_defaults.empty()) result.source["planar_defaults"] = planar_defaults;
  if (!ekf_settings.empty()) result.source["noise_sources"] = settings_json(ekf_settings);
  return result;
}

void print_results(const ExperimentResult& result, const std::string& title) {
  std::printf("%s: %d iterations\n", title.c_str(), result.iterations);
  // The plane half scores planes (the key-point error e_ends), the point half landmarks: the
  // family that ran says which (ExperimentResult::half).
  const bool planar = result.half == ScenarioHalf::Planes;
  // Errors are in the world's units: a simulation's own, metres for recorded data.
  std::printf("%-20s %-8s %10s %14s %10s %10s %10s\n", "algorithm", "status", planar ? "planes" : "landmarks",
              planar ? "map err" : "landmark err", "pos err", "median ms", "p95 ms");
  auto line = [](const SummaryRow& r) {
    std::printf("%-20s %-8s %10d %14.4g %10.4g %10.4g %10.4g\n", r.algorithm.c_str(),
                std::string(to_string(r.status.kind)).c_str(), r.landmarks_on_map, r.final_mean_landmark_error,
                r.final_position_error, r.runtime.median_ms, r.runtime.p95_ms);
  };
  for (const SummaryRow& r : result.rows) line(r);
  if (result.ratio) {
    const SummaryRow& r = *result.ratio;
    std::printf("%-20s %-8s %10s %14.3g %10.3g %10.3g %10.3g\n", r.algorithm.c_str(), "ratio", "",
                r.final_mean_landmark_error, r.final_position_error, r.runtime.median_ms, r.runtime.p95_ms);
    const std::string a = r.algorithm.substr(0, r.algorithm.find('/')), b = r.algorithm.substr(a.size() + 1);
    std::printf("(ratio: %s's score divided by %s's over the %d iterations both processed; below 1, %s's is lower)\n",
                a.c_str(), b.c_str(), r.iterations, a.c_str());
  }
  std::printf("(landmark err: mean distance of each mapped landmark from the truth at the end; pos err: of the\n"
              " last pose; in the world's units, metres for recorded data; ms: time per iteration)\n");
  for (const SummaryRow& r : result.rows)
    if (!r.status.is_ok()) std::printf("%s: %s\n", r.algorithm.c_str(), r.status.text().c_str());
}

}  // namespace relslam::eval
