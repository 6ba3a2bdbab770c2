#include "relslam/eval/cli/commands/tune_ekf.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/batch.hpp"
#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/io/run_folder.hpp"
#include "relslam/eval/io/text_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <numbers>

namespace relslam::eval {
namespace {

std::string text_of(double v) {
  std::string s;
  append_number(s, v);
  return s;
}

// The motion noise the q_scale factors multiply: the spec's starting point (relative_point
// §7), fixed so a tuning run does not depend on what an earlier one put in the scenario.
constexpr double kBaseStdsQ[] = {0.35, 0.35, 0.35, 0.005, 0.005, 0.005, 0.005};

std::vector<GridAxis> tuning_axes(const TuneEkfArgs& args) {
  GridAxis range{"std_range", {}}, angle{"std_angle_deg", {}}, q{"q_scale", {}};
  for (double v : args.std_range) range.values.push_back({text_of(v), {"ekf6d.std_range=" + text_of(v)}});
  for (double v : args.std_angle_deg)
    angle.values.push_back({text_of(v), {"ekf6d.std_yaw_deg=" + text_of(v), "ekf6d.std_pitch_deg=" + text_of(v)}});
  for (double scale : args.q_scale) {
    std::string list = "[";
    for (double s : kBaseStdsQ) list += (list.size() > 1 ? "," : "") + text_of(s * scale);
    q.values.push_back({text_of(scale), {"ekf6d.stds_q=" + list + "]"}});
  }
  return {range, angle, q};
}

struct Trial {
  const BatchResult* result;
  const SummaryRow* ekf;  // null when the run itself failed
  bool ok() const { return ekf && ekf->status.is_ok(); }
  // The thesis's criterion, the landmark error; averaged over the iterations so the whole run
  // counts, not only its last step [C].
  double score() const { return ok() ? ekf->mean_landmark_error : std::numeric_limits<double>::infinity(); }
};

std::vector<Trial> ranked(const std::vector<BatchResult>& results) {
  std::vector<Trial> trials;
  for (const BatchResult& r : results) {
    const SummaryRow* ekf = nullptr;
    for (const SummaryRow& s : r.rows)
      if (s.algorithm == "ekf6d") ekf = &s;
    trials.push_back({&r, ekf});
  }
  std::stable_sort(trials.begin(), trials.end(), [](const Trial& a, const Trial& b) { return a.score() < b.score(); });
  return trials;
}

void write_table(const std::filesystem::path& file, const std::vector<Trial>& trials) {
  CsvWriter table(file, {"rank", "std_range", "std_angle_deg", "q_scale", "status", "iterations", "mean_landmark_error",
                         "final_mean_landmark_error", "final_position_error", "landmarks_on_map", "runtime_median_ms"});
  for (std::size_t i = 0; i < trials.size(); ++i) {
    const Trial& t = trials[i];
    const auto& l = t.result->job.labels;
    const std::string status = !t.result->error.empty() ? "error: " + t.result->error
                               : t.ekf                  ? t.ekf->status.text()
                                                        : "no ekf6d row";
    std::vector<std::optional<double>> numbers(6);
    if (t.ekf)
      numbers = {static_cast<double>(t.ekf->iterations),
                 t.ekf->mean_landmark_error,
                 t.ekf->final_mean_landmark_error,
                 t.ekf->final_position_error,
                 static_cast<double>(t.ekf->landmarks_on_map),
                 t.ekf->runtime.median_ms};
    table.row_fields({std::to_string(i + 1), l[0], l[1], l[2], status}, numbers);
  }
  table.close();
}

// The winning values as the scenario's ekf6d section takes them.
nlohmann::json best_section(const Trial& best) {
  nlohmann::json section;
  for (const std::string& o : best.result->job.overrides) {
    const std::size_t eq = o.find('=');
    const std::string key = o.substr(0, eq);
    if (key.rfind("ekf6d.", 0) == 0) section[key.substr(6)] = nlohmann::json::parse(o.substr(eq + 1));
  }
  return section;
}

}  // namespace

void add_tune_ekf(CLI::App& app, TuneEkfArgs& args) {
  CLI::App* cmd = add_scenario_command(
      app, args, "tune-ekf", "Grid-search the EKF's sensor standard deviations for the lowest landmark error",
      "The thesis tuned the three sensor-model standard deviations of MRPT's EKF (range, yaw, pitch)\n"
      "to minimise the landmark error. This runs the EKF alone on the scenario with the seed shifted by\n"
      "--seed-offset (tuning never sees an experiment's data), for --iterations iterations, over the grid\n"
      "std_range x std_angle_deg (yaw = pitch) x q_scale (times the motion noise stds_q = 0.35 0.35 0.35\n"
      "0.005 0.005 0.005 0.005), --jobs runs at a time.\n"
      "Writes tune.csv (every trial, best first, ranked by the landmark error averaged over the run),\n"
      "best.json (the ekf6d section to put in the scenario files) and manifest.json.",
      "scenarios/s-ekf-f8.json");
  cmd->add_option("--std-range", args.std_range, "Range std. deviations to try, units")
      ->capture_default_str()
      ->delimiter(',');
  cmd->add_option("--std-angle-deg", args.std_angle_deg, "Yaw = pitch std. deviations to try, degrees")
      ->capture_default_str()
      ->delimiter(',');
  cmd->add_option("--q-scale", args.q_scale, "Factors on the motion noise (0.35 x3, 0.005 x4)")
      ->capture_default_str()
      ->delimiter(',');
  cmd->add_option("--iterations", args.iterations, "Iterations per trial")
      ->capture_default_str()
      ->check(CLI::Range(10, 1000000));
  cmd->add_option("--seed-offset", args.seed_offset, "Tuning seed = scenario seed + this")->capture_default_str();
  cmd->add_option("--jobs,-j", args.jobs, "Trials at a time")->capture_default_str()->check(CLI::Range(1, 256));
}

int run_tune_ekf(const TuneEkfArgs& args, const std::vector<std::string>& command_line) {
  for (const auto& [name, values] : {std::pair{"--std-range", &args.std_range},
                                     {"--std-angle-deg", &args.std_angle_deg},
                                     {"--q-scale", &args.q_scale}})
    for (double v : *values)
      if (!(v > 0) || !std::isfinite(v)) throw InputError(name, 0, text_of(v), "values must be positive numbers");
  std::vector<std::string> base = args.set;
  // The EKF alone, and only the files scoring needs.
  base.insert(base.end(), {"algorithms=ekf6d", "sim.iterations=" + std::to_string(args.iterations),
                           "output.observations_csv=false", "output.rawlog=false"});
  const LoadedScenario loaded = load_checked(args.scenario, base);
  const int seed = static_cast<int>(loaded.scenario.seed) + args.seed_offset;
  const std::vector<GridAxis> axes = tuning_axes(args);
  const std::vector<BatchJob> jobs = grid_jobs(axes, {seed}, std::filesystem::path(args.out) / "trials");
  check_jobs_load(args.scenario, base, jobs);
  prepare_run_folder(args.out, args.force);
  if (!args.quiet)
    std::printf("tune-ekf %s: %zu trials of %d iterations on seed %d, %d at a time\n", loaded.scenario.name.c_str(),
                jobs.size(), args.iterations, seed, args.jobs);

  const std::vector<BatchResult> results = run_batch(args.scenario, base, jobs, args.jobs, !args.quiet, command_line);
  const std::vector<Trial> trials = ranked(results);
  write_table(std::filesystem::path(args.out) / "tune.csv", trials);
  nlohmann::json tuning = {
      {"criterion", "mean_landmark_error of ekf6d, averaged over the iterations"},
      {"seed", seed},
      {"iterations", args.iterations},
      {"grid", {{"std_range", args.std_range}, {"std_angle_deg", args.std_angle_deg}, {"q_scale", args.q_scale}}},
      {"trials", jobs.size()}};
  const bool found = !trials.empty() && trials.front().ok();
  if (found) {
    tuning["best"] = {{"ekf6d", best_section(trials.front())},
                      {"mean_landmark_error", trials.front().score()},
                      {"labels", trials.front().result->job.labels}};
    std::ofstream(std::filesystem::path(args.out) / "best.json") << tuning["best"].dump(2) << '\n';
  }
  write_manifest(args.out, loaded.scenario, {"tune-ekf", command_line, args.scenario, args.set}, {{"tuning", tuning}});
  if (!found) throw std::runtime_error("no trial of the EKF succeeded; see " + args.out + "/tune.csv");
  if (!args.quiet) {
    std::printf("%4s %10s %14s %8s %14s %10s\n", "rank", "std_range", "std_angle_deg", "q_scale", "mean lm err",
                "median ms");
    for (std::size_t i = 0; i < std::min<std::size_t>(trials.size(), 8); ++i) {
      const Trial& t = trials[i];
      const auto& l = t.result->job.labels;
      std::printf("%4zu %10s %14s %8s %14.4g %10.4g\n", i + 1, l[0].c_str(), l[1].c_str(), l[2].c_str(), t.score(),
                  t.ekf ? t.ekf->runtime.median_ms : 0.0);
    }
    std::printf("best: \"ekf6d\": %s\nwrote %s (tune.csv, best.json, trials/)\n",
                best_section(trials.front()).dump().c_str(), args.out.c_str());
  }
  return 0;
}

}  // namespace relslam::eval
