#include "relslam/eval/experiments/experiment.hpp"

#include "stream_to_recorders.hpp"

#include "relslam/eval/algorithms/registry.hpp"
#include "relslam/eval/config/point_bounds.hpp"
#include "relslam/eval/experiments/ekf_log_settings.hpp"
#include "relslam/eval/experiments/interruption.hpp"
#include "relslam/eval/experiments/planar_experiment.hpp"
#include "relslam/eval/experiments/rawlog_defaults.hpp"
#include "relslam/eval/experiments/require_algorithms.hpp"
#include "relslam/eval/io/progress.hpp"
#include "relslam/eval/io/run_folder.hpp"
#include "relslam/eval/sources/simulation_source.hpp"
#include "relslam/point/noise_estimate.hpp"
#include "relslam/point/rlt_mapper.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <sstream>

namespace relslam::eval {

Experiment::Experiment(const LoadedScenario& loaded, FrameSource& source, const std::filesystem::path& out)
    : source_(source), out_(out) {
  require_algorithms(loaded);
  const AlgorithmContext context{loaded.scenario, source.sensor()};
  for (const std::string& name : loaded.scenario.algorithms)
    recorders_.push_back(
        std::make_unique<AlgorithmRecorder>(make_algorithm(name, context), source.truth(), out / name));
}

ExperimentResult Experiment::run(bool progress) {
  const auto start = std::chrono::steady_clock::now();
  Progress bar(source_.label(), source_.frames(), progress);
  ExperimentResult result;
  // Interrupted, the run finishes with the frames processed so far, every row says where it was
  // cut, and the command marks the manifest "interrupted".
  const std::optional<int> stopped_at = stream_to_recorders(source_, recorders_, bar);
  result.interrupted = stopped_at.has_value();
  for (auto& recorder : recorders_) result.rows.push_back(recorder->finish());
  if (stopped_at) mark_interrupted(result.rows, *stopped_at);
  // The Relative Point / EKF ratios, over the iterations both processed: against the 6D EKF,
  // or else the planar one with odometry.
  auto index_of = [&](const char* name) {
    for (std::size_t i = 0; i < recorders_.size(); ++i)
      if (recorders_[i]->name() == name) return static_cast<int>(i);
    return -1;
  };
  const int rp = index_of("relative_point");
  int ekf = index_of("ekf6d");
  if (ekf < 0) ekf = index_of("ekf2d");
  if (rp >= 0 && ekf >= 0) {
    const int common = std::min(result.rows[rp].iterations, result.rows[ekf].iterations);
    if (common > 0)
      result.ratio = ratio_row(recorders_[rp]->summary_over(common), recorders_[ekf]->summary_over(common));
  }
  // Every other algorithm over the batch optimum, the accuracy floor over all the frames (an
  // EKF stopped early is compared as it stopped).
  if (const int optimum = index_of("batch_optimum"); optimum >= 0)
    for (std::size_t i = 0; i < result.rows.size(); ++i)
      if (static_cast<int>(i) != optimum) result.optimum_ratios.push_back(ratio_row(result.rows[i], result.rows[optimum]));
  write_summary(out_ / "summary.csv", result.rows, result.ratio, result.optimum_ratios);
  bar.finish();
  result.iterations = static_cast<int>(source_.frames());
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.source = source_.describe();
  return result;
}

ExperimentResult simulate_and_run(const LoadedScenario& loaded, const std::filesystem::path& out, bool progress) {
  if (loaded.scenario.kind == ScenarioKind::Planar) return simulate_planar_and_run(loaded, out, progress);
  require_algorithms(loaded);
  SimulationSource source(loaded);
  source.record_into(out);
  Experiment experiment(loaded, source, out);
  return experiment.run(progress);
}

namespace {

// Iterations of the pilot run that estimates the noise of a rawlog without a sensor model: a
// few final groups (look-ahead 60) and many temporary ones form in them, hundreds of member
// pairs at the densities of issue 16 [C].
constexpr long long kNoisePilotIterations = 300;

// The noise of data that states none, estimated online (issue 16): pilot runs of Relative Point
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
  // Planar runs score planes (the key-point error e_ends), the others landmarks.
  const bool planar = !result.rows.empty() && result.rows.front().planar.has_value();
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
