#include "relslam/eval/cli/commands/tune_ekf.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/batch.hpp"
#include "relslam/eval/experiments/ekf_log_settings.hpp"
#include "relslam/eval/experiments/experiment.hpp"
#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/io/run_folder.hpp"
#include "relslam/eval/io/text_output.hpp"
#include "relslam/eval/sources/rawlog_source.hpp"

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

// The motion noise the q_scale factors multiply: our starting point,
// fixed so a tuning run does not depend on what an earlier one put in the scenario.
constexpr double kBaseStdsQ[] = {0.35, 0.35, 0.35, 0.005, 0.005, 0.005, 0.005};

// `base_q`: the motion noise q_scale multiplies.
std::vector<GridAxis> tuning_axes(const TuneEkfArgs& args, const std::vector<double>& base_q) {
  GridAxis range{"std_range", {}}, angle{"std_angle_deg", {}}, q{"q_scale", {}};
  for (double v : args.std_range) range.values.push_back({text_of(v), {"ekf6d.std_range=" + text_of(v)}});
  for (double v : args.std_angle_deg)
    angle.values.push_back({text_of(v), {"ekf6d.std_yaw_deg=" + text_of(v), "ekf6d.std_pitch_deg=" + text_of(v)}});
  for (double scale : args.q_scale) {
    std::string list = "[";
    for (double s : base_q) list += (list.size() > 1 ? "," : "") + text_of(s * scale);
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

// The best trials as a table.
void print_ranking(const std::vector<Trial>& trials) {
  std::printf("%4s %10s %14s %8s %14s %10s\n", "rank", "std_range", "std_angle_deg", "q_scale", "mean lm err",
              "median ms");
  for (std::size_t i = 0; i < std::min<std::size_t>(trials.size(), 8); ++i) {
    const Trial& t = trials[i];
    const auto& l = t.result->job.labels;
    std::printf("%4zu %10s %14s %8s %14.4g %10.4g\n", i + 1, l[0].c_str(), l[1].c_str(), l[2].c_str(), t.score(),
                t.ekf ? t.ekf->runtime.median_ms : 0.0);
  }
}

void print_rawlog_tuning(const nlohmann::json& tuning, const std::vector<Trial>& trials, const std::string& out) {
  print_ranking(trials);
  const auto error = [](const nlohmann::json& run) {
    if (!run.contains("final_mean_landmark_error")) return run["status"].dump();
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", run["final_mean_landmark_error"].get<double>());
    return std::string(text);
  };
  const nlohmann::json& split = tuning["split"];
  // [first, end) as the first and last frame.
  const auto frames = [](const nlohmann::json& range) {
    return std::to_string(range[0].get<int>()) + ".." + std::to_string(range[1].get<int>() - 1);
  };
  std::printf("best: \"ekf6d\": %s (tuned on frames %s)\n", tuning["best"]["ekf6d"].dump().c_str(),
              frames(split["tuning_frames"]).c_str());
  std::printf("held out, frames %s: final mean landmark error %s tuned, %s untuned (log/default settings)\n",
              frames(split["held_out_frames"]).c_str(), error(tuning["held_out"]["tuned"]).c_str(),
              error(tuning["held_out"]["untuned"]).c_str());
  std::printf("wrote %s (tune.csv, best.json, trials/, held_out/, held_out_untuned/)\n", out.c_str());
}

// ---- On a recorded log: tune on its first part, score the winner on the rest ----

// The scenario (file or defaults) with --set, the EKF alone, and the values a trial tries,
// marked as tune-ekf's so the trial's manifest says "tuned".
LoadedScenario rawlog_scenario(const TuneEkfArgs& args, const std::vector<std::string>& tried) {
  std::vector<Override> overrides;
  for (const std::string& text : args.set) overrides.push_back(parse_override(text));
  overrides.push_back(parse_override("algorithms=ekf6d"));
  for (const std::string& text : tried) {
    overrides.push_back(parse_override(text));
    overrides.back().origin = kTunedOrigin;
  }
  return args.scenario.empty() ? parse_scenario("{}", "(defaults)", overrides)
                               : load_scenario(args.scenario, overrides);
}

RawlogFiles rawlog_part(const TuneEkfArgs& args, int first, int end) {
  RawlogFiles files{args.rawlog, args.truth_path, args.truth_landmarks};
  files.first_frame = first;
  files.end_frame = end;
  return files;
}

// One run of the EKF on a part of the log into job.folder, kept as a sweep keeps a run.
BatchResult rawlog_trial(const TuneEkfArgs& args, const BatchJob& job, const RawlogFiles& files,
                         const std::vector<std::string>& command_line) {
  BatchResult r{job, "", {}};
  try {
    const LoadedScenario loaded = rawlog_scenario(args, job.overrides);
    prepare_run_folder(job.folder, false);
    const ExperimentResult e = run_on_rawlog(loaded, files, job.folder, false);
    write_manifest(job.folder, loaded.scenario, {"tune-ekf", command_line, args.scenario, job.overrides}, e.source);
    r.rows = e.rows;
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  return r;
}

nlohmann::json held_out_json(const BatchResult& r) {
  if (!r.error.empty() || r.rows.empty()) return {{"status", "error: " + r.error}};
  const SummaryRow& ekf = r.rows.front();
  return {{"status", ekf.status.text()},
          {"final_mean_landmark_error", ekf.final_mean_landmark_error},
          {"mean_landmark_error", ekf.mean_landmark_error},
          {"folder", r.job.folder.string()}};
}

// The trials of the grid on frames [0, split), best first.
std::vector<BatchResult> rawlog_trials(const TuneEkfArgs& args, const LoadedScenario& loaded, const Rawlog& log,
                                       int split, const std::vector<std::string>& command_line) {
  // q_scale multiplies the motion noise a run on this log would use (sized from its odometry).
  Scenario adapted = loaded.scenario;
  apply_log_ekf_settings(adapted, loaded, log);
  std::vector<BatchJob> jobs =
      grid_jobs(tuning_axes(args, adapted.ekf6d.stds_q), {0}, std::filesystem::path(args.out) / "trials");
  for (BatchJob& job : jobs) {  // a log has no seed: drop grid_jobs' seed folder and setting
    job.folder = job.folder.parent_path();
    job.overrides.pop_back();
  }
  std::vector<BatchResult> results;
  for (const BatchJob& job : jobs)
    results.push_back(rawlog_trial(args, job, rawlog_part(args, 0, split), command_line));
  return results;
}

int run_tune_ekf_rawlog(const TuneEkfArgs& args, const std::vector<std::string>& command_line) {
  if (args.truth_path.empty() || args.truth_landmarks.empty())
    throw InputError("", 0, "--truth-path",
                     "tune-ekf --rawlog scores against ground truth: give --truth-path and --truth-landmarks");
  const LoadedScenario loaded = rawlog_scenario(args, {});
  const RawlogSource whole(rawlog_part(args, 0, -1));  // reads and checks the files before the folder exists
  const int frames = static_cast<int>(whole.frames());
  const int split = static_cast<int>(std::lround(frames * args.split));
  if (split < 10 || frames - split < 10)
    throw InputError(args.rawlog, 0, "--split",
                     "needs at least 10 frames on each side; " + std::to_string(frames) + " frames split at " +
                         std::to_string(split));
  prepare_run_folder(args.out, args.force);
  if (!args.quiet)
    std::printf("tune-ekf %s: tuning on frames 0..%d, scoring the best on the held-out frames %d..%d\n",
                args.rawlog.c_str(), split - 1, split, frames - 1);
  const std::vector<BatchResult> results = rawlog_trials(args, loaded, whole.log(), split, command_line);
  const std::vector<Trial> trials = ranked(results);
  write_table(std::filesystem::path(args.out) / "tune.csv", trials);
  nlohmann::json tuning = {
      {"criterion", "mean_landmark_error of ekf6d on the tuning frames, averaged over the iterations"},
      {"rawlog", args.rawlog},
      {"split", {{"tuning_frames", {0, split}}, {"held_out_frames", {split, frames}}, {"share", args.split}}},
      {"grid", {{"std_range", args.std_range}, {"std_angle_deg", args.std_angle_deg}, {"q_scale", args.q_scale}}},
      {"trials", results.size()}};
  const bool found = !trials.empty() && trials.front().ok();
  if (found) {
    const Trial& best = trials.front();
    const RawlogFiles rest = rawlog_part(args, split, frames);
    const std::filesystem::path out(args.out);
    const BatchResult tuned =
        rawlog_trial(args, {out / "held_out", best.result->job.overrides, {}, 0}, rest, command_line);
    const BatchResult untuned = rawlog_trial(args, {out / "held_out_untuned", {}, {}, 0}, rest, command_line);
    tuning["best"] = {
        {"ekf6d", best_section(best)}, {"mean_landmark_error", best.score()}, {"labels", best.result->job.labels}};
    tuning["held_out"] = {{"tuned", held_out_json(tuned)}, {"untuned", held_out_json(untuned)}};
    std::ofstream(out / "best.json") << tuning["best"].dump(2) << '\n';
  }
  write_manifest(args.out, loaded.scenario, {"tune-ekf", command_line, args.scenario, args.set}, {{"tuning", tuning}});
  if (!found) throw std::runtime_error("no trial of the EKF succeeded; see " + args.out + "/tune.csv");
  if (!args.quiet) print_rawlog_tuning(tuning, trials, args.out);
  return 0;
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
      "best.json (the ekf6d section to put in the scenario files) and manifest.json.\n"
      "With --rawlog (and --truth-path, --truth-landmarks) it tunes on the log's first --split share of frames,\n"
      "q_scale multiplying the motion noise sized from the log, and scores the best and the untuned settings\n"
      "on the rest (held_out/, held_out_untuned/), which tuning never saw.",
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
  cmd->get_option("scenario")->required(false);
  cmd->add_option("--rawlog", args.rawlog, "Tune on this MRPT rawlog instead of the simulation (scenario optional)");
  cmd->add_option("--truth-path", args.truth_path, "With --rawlog: robot path, rows x y z yaw pitch roll (MRPT)");
  cmd->add_option("--truth-landmarks", args.truth_landmarks, "With --rawlog: landmarks, rows x y z ... id (MRPT)");
  cmd->add_option("--split", args.split, "With --rawlog: share of the frames to tune on; the rest scores the best")
      ->capture_default_str()
      ->check(CLI::Range(0.05, 0.95));
}

int run_tune_ekf(const TuneEkfArgs& args, const std::vector<std::string>& command_line) {
  if (args.scenario.empty() && args.rawlog.empty())
    throw InputError("", 0, "scenario", "give a scenario file, or --rawlog to tune on recorded observations");
  if (args.rawlog.empty() && (!args.truth_path.empty() || !args.truth_landmarks.empty()))
    throw InputError("", 0, "--truth-path", "ground-truth files go with --rawlog");
  for (const auto& [name, values] : {std::pair{"--std-range", &args.std_range},
                                     {"--std-angle-deg", &args.std_angle_deg},
                                     {"--q-scale", &args.q_scale}})
    for (double v : *values)
      if (!(v > 0) || !std::isfinite(v)) throw InputError(name, 0, text_of(v), "values must be positive numbers");
  if (!args.rawlog.empty()) return run_tune_ekf_rawlog(args, command_line);
  std::vector<std::string> base = args.set;
  // The EKF alone, and only the files scoring needs.
  base.insert(base.end(), {"algorithms=ekf6d", "sim.iterations=" + std::to_string(args.iterations),
                           "output.observations_csv=false", "output.rawlog=false"});
  const LoadedScenario loaded = load_checked(args.scenario, base);
  const int seed = static_cast<int>(loaded.scenario.seed) + args.seed_offset;
  const std::vector<GridAxis> axes =
      tuning_axes(args, std::vector<double>(std::begin(kBaseStdsQ), std::end(kBaseStdsQ)));
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
    print_ranking(trials);
    std::printf("best: \"ekf6d\": %s\nwrote %s (tune.csv, best.json, trials/)\n",
                best_section(trials.front()).dump().c_str(), args.out.c_str());
  }
  return 0;
}

}  // namespace relslam::eval
