#include "relslam/eval/cli/commands/run.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/experiment.hpp"
#include "relslam/eval/experiments/interruption.hpp"
#include "relslam/eval/experiments/rawlog_defaults.hpp"
#include "relslam/eval/experiments/require_algorithms.hpp"
#include "relslam/eval/experiments/source_registry.hpp"
#include "relslam/eval/io/run_folder.hpp"

#include <cstdio>

namespace relslam::eval {

void add_run(CLI::App& app, RunArgs& args) {
  CLI::App* cmd = app.add_subcommand("run", "Run a scenario's algorithms on simulated or recorded observations");
  cmd->description(
      "Feed every frame of one observation stream to each algorithm the scenario lists (key `algorithms`),\n"
      "scoring them against the truth as they go. The stream is the scenario's simulation, or with --rawlog\n"
      "an MRPT rawlog (any range-bearing landmark data set), optionally scored against ground truth in\n"
      "MRPT's text formats. Without a scenario: relative_point and ekf6d, or for a planar (2D) rawlog\n"
      "relative_point and ekf2d, Relative Point bridged by the log's odometry as at Victoria Park. Writes one\n"
      "folder per algorithm (iterations.csv, landmarks.csv, trajectory.tum), summary.csv (with the\n"
      "relative_point/ekf6d or /ekf2d ratios when both ran; a status 'lost: ...' when an algorithm's pose came\n"
      "from unmapped points or the like in most iterations) and manifest.json.");
  cmd->add_option("scenario", args.scenario, "Scenario file, e.g. scenarios/s-ekf-f8.json (optional with --rawlog)");
  cmd->add_option("--out,-o", args.out, "Run folder to create (refused if it exists and is not empty)")->required();
  cmd->add_option("--set", args.set, "Override a scenario key, e.g. --set sim.density=50 (repeatable)");
  cmd->add_option("--rawlog", args.rawlog, "Read the observations from this MRPT rawlog instead of simulating");
  cmd->add_option("--planes", args.planes,
                  "Read plane observations from this CSV (the columns of a planar run's plane_observations.csv: "
                  "iteration, index, kp1_x, kp1_z, kp2_x, kp2_z; optional true_wall, kp1_true_end, kp2_true_end, "
                  "y_lo, y_hi) instead of simulating");
  cmd->add_option("--truth-path", args.truth_path,
                  "With --rawlog: robot path, rows x y z yaw pitch roll (MRPT); with --planes: "
                  "ground_truth_poses.csv (iteration, x, z, heading_rad) or a TUM file");
  cmd->add_option("--truth-landmarks", args.truth_landmarks, "With --rawlog: landmarks, rows x y z ... id (MRPT)");
  cmd->add_option("--truth-walls", args.truth_walls,
                  "With --planes: the true walls (ground_truth_walls.csv: id, a_x, a_z, b_x, b_z, height)");
  cmd->add_flag("--force", args.force, "Replace an earlier run in the --out folder");
  cmd->add_flag("--quiet,-q", args.quiet, "Print nothing but errors");
}

namespace {

// The observations the run reads instead of simulating: checks the flags that go together.
void check_inputs(const RunArgs& args) {
  if (!args.rawlog.empty() && !args.planes.empty())
    throw InputError("", 0, "--planes", "give --rawlog or --planes, not both");
  if (args.scenario.empty() && args.rawlog.empty() && args.planes.empty())
    throw InputError("", 0, "scenario", "give a scenario file, or --rawlog / --planes to run on recorded observations");
  if (args.rawlog.empty() && args.planes.empty() && !args.truth_path.empty())
    throw InputError("", 0, "--truth-path", "ground-truth files go with --rawlog or --planes");
  if (args.rawlog.empty() && !args.truth_landmarks.empty())
    throw InputError("", 0, "--truth-landmarks", "goes with --rawlog");
  if (args.planes.empty() && !args.truth_walls.empty()) throw InputError("", 0, "--truth-walls", "goes with --planes");
}

RawlogFiles rawlog_files(const RunArgs& args) {
  RawlogFiles files{args.rawlog, std::nullopt, std::nullopt};
  if (!args.truth_path.empty()) files.truth_path = args.truth_path;
  if (!args.truth_landmarks.empty()) files.truth_landmarks = args.truth_landmarks;
  return files;
}

}  // namespace

int run_run(const RunArgs& args, const std::vector<std::string>& command_line) {
  check_inputs(args);
  // Without a scenario file, the defaults: Relative Point and the EKF that fits a rawlog (the
  // planar one for a planar log, rawlog_defaults.hpp); the planar defaults for plane files.
  std::vector<std::string> set = args.set;
  if (args.scenario.empty()) {
    const std::vector<std::string> defaults =
        args.planes.empty() ? default_rawlog_settings(rawlog_files(args))
                            : std::vector<std::string>{"kind=planar", "algorithms=relative_plane"};
    set.insert(set.begin(), defaults.begin(), defaults.end());
  }
  const LoadedScenario loaded =
      args.scenario.empty() ? parse_checked("{}", "(defaults)", set) : load_checked(args.scenario, set);
  // Input before output: what can be checked without reading the observations is checked before
  // the folder exists (a bad input found later leaves a folder the corrected command reuses).
  require_algorithms(loaded);
  prepare_run_folder(args.out, args.force);
  const Invocation invocation{"run", command_line, args.scenario, set};
  catch_interrupts();  // before the manifest says running: a signal from then on is seen
  write_manifest(args.out, loaded.scenario, invocation, {}, kRunStatusRunning);

  ExperimentResult result;
  try {
    const RunInputs inputs{args.rawlog, args.planes, args.truth_path, args.truth_landmarks, args.truth_walls};
    result = run_from_source(loaded, inputs, args.out, !args.quiet);
  } catch (const std::exception& e) {
    record_failure(args.out, loaded.scenario, invocation, e);
    throw;
  }
  nlohmann::json results = nlohmann::json::array();
  for (const SummaryRow& r : result.rows)
    results.push_back({{"algorithm", r.algorithm},
                       {"status", r.status.text()},
                       {"final_mean_landmark_error", r.final_mean_landmark_error},
                       {"final_position_error", r.final_position_error},
                       {"runtime_median_ms", r.runtime.median_ms}});
  nlohmann::json extra = result.source;
  extra["results"] = results;
  extra["wall_time_s"] = result.seconds;
  write_manifest(args.out, loaded.scenario, invocation, extra,
                 result.interrupted ? kRunStatusInterrupted : kRunStatusOk);
  if (result.interrupted) {
    std::fprintf(stderr, "relslam: interrupted; %s holds the iterations processed\n", args.out.c_str());
    return kInterruptedExit;
  }
  if (!args.quiet) {
    print_results(result, !args.rawlog.empty()   ? args.rawlog
                          : !args.planes.empty() ? args.planes
                                                 : loaded.scenario.name);
    std::printf("wrote %s in %.1f s\n", args.out.c_str(), result.seconds);
  }
  return 0;
}

}  // namespace relslam::eval
