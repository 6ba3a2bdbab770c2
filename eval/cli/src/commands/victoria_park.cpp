#include "relslam/eval/cli/commands/victoria_park.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/interruption.hpp"
#include "relslam/eval/experiments/victoria_park_experiment.hpp"
#include "relslam/eval/io/range_bearing.hpp"
#include "relslam/eval/io/rawlog.hpp"
#include "relslam/eval/io/run_folder.hpp"
#include "relslam/eval/sources/victoria_park_source.hpp"

#include <cstdio>

namespace relslam::eval {
namespace {

VictoriaParkLog read_log(const std::string& flag) {
  const std::filesystem::path dir = victoria_park_dir(flag);
  if (!std::filesystem::exists(dir / "measurements.dat"))
    throw InputError(dir.string(), 0, "--data",
                     "no Victoria Park data here (measurements.dat); pass --data DIR or set RELSLAM_VICTORIA_PARK");
  return read_victoria_park(dir);
}

}  // namespace

void add_victoria_park(CLI::App& app, VictoriaParkArgs& args) {
  args.scenario = "scenarios/victoria-park.json";
  CLI::App* cmd = add_scenario_command(
      app, args, "victoria-park", "Run the algorithms on the Victoria Park data set and compare with GPS (thesis 6.8)",
      "Feed a window of Victoria Park's laser scans (the tree detections, as robot-frame points in the scan\n"
      "plane) to the scenario's algorithms: relative_point, and MRPT's planar EKF with the vehicle's\n"
      "dead reckoning (ekf2d, Ackermann model from inputs.dat) and without (ekf2d_no_odometry). Writes the\n"
      "run folder of relslam run plus scans.csv (per scan: trees, odometry, GPS), gps.tum,\n"
      "gps_comparison.csv (ATE of each trajectory against GPS after the best 2D rigid alignment; GPS has no\n"
      "orientation), map_comparison.csv (each map against ekf2d's after a similarity fit) and, per\n"
      "algorithm, the trajectory and landmarks in the GPS frame. Windows: 1181:1642 and 4220:4634 (the\n"
      "thesis's) or all; the Relative algorithm needs 3 trees in view, and --bridge carries its pose over\n"
      "scans with fewer by dead reckoning and checks its registrations against it (beyond the thesis;\n"
      "scenarios/victoria-park-bridged.json runs the whole log that way, 1.8 m from GPS).",
      "scenarios/victoria-park.json");
  cmd->get_option("scenario")->required(false)->capture_default_str();
  cmd->add_option("--data", args.data,
                  "Data folder (default $RELSLAM_VICTORIA_PARK, else ../shared/datasets/victoria_park)");
  cmd->add_option("--window,-w", args.window, "Scans FIRST:LAST (1-based, of 7249) or all (default: the scenario's)");
  cmd->add_flag(
      "--bridge", args.bridge,
      "Relative Point: bridge scans with fewer than 3 trees by dead reckoning, and check registrations against it");
}

int run_victoria_park_command(const VictoriaParkArgs& args, const std::vector<std::string>& command_line) {
  std::vector<std::string> set = args.set;
  if (!args.window.empty()) set.push_back("victoria_park.window=" + args.window);
  if (args.bridge) set.push_back("relative_point.use_odometry=true");
  const LoadedScenario loaded = load_checked(args.scenario, set);
  const VictoriaParkLog log = read_log(args.data);
  prepare_run_folder(args.out, args.force);
  const Invocation invocation{"victoria-park", command_line, args.scenario, set};
  catch_interrupts();  // before the manifest says running: a signal from then on is seen
  write_manifest(args.out, loaded.scenario, invocation, {}, kRunStatusRunning);
  VictoriaParkResult result;
  try {
    result = run_victoria_park(loaded, log, args.out, !args.quiet);
  } catch (const std::exception& e) {
    record_failure(args.out, loaded.scenario, invocation, e);
    throw;
  }
  nlohmann::json extra = result.experiment.source;
  extra["data"] = victoria_park_dir(args.data).string();
  extra["wall_time_s"] = result.experiment.seconds;
  write_manifest(args.out, loaded.scenario, invocation, extra,
                 result.experiment.interrupted ? kRunStatusInterrupted : kRunStatusOk);
  if (result.experiment.interrupted) {
    std::fprintf(stderr, "relslam: interrupted; %s holds the scans processed\n", args.out.c_str());
    return kInterruptedExit;
  }
  if (!args.quiet) {
    print_victoria_park(result, "victoria park " + loaded.scenario.victoria_park.window);
    std::printf("wrote %s in %.1f s\n", args.out.c_str(), result.experiment.seconds);
  }
  return 0;
}

void add_convert(CLI::App& app, ConvertVictoriaParkArgs& args) {
  CLI::App* convert = app.add_subcommand("convert", "Convert a data set to an MRPT rawlog");
  convert->require_subcommand(1);
  CLI::App* vp = convert->add_subcommand("victoria-park", "Victoria Park as an MRPT rawlog (odometry + bearing-range)");
  vp->description(
      "Write the scans of the Victoria Park data set as an action-first MRPT rawlog: per scan a\n"
      "CActionRobotMovement2D with the dead-reckoned motion since the previous scan (Ackermann model, the\n"
      "laser's pose) and a sensory frame with one CObservationBearingRange (range, yaw = bearing - pi/2,\n"
      "ids -1). MRPT's rawlog-edit and kf-slam replay it; relslam run --rawlog reads it back.");
  vp->add_option("--out,-o", args.out, "Rawlog to write")->required();
  vp->add_option("--data", args.data,
                 "Data folder (default $RELSLAM_VICTORIA_PARK, else ../shared/datasets/victoria_park)");
  vp->add_option("--window,-w", args.window, "Scans FIRST:LAST (1-based) or all")->capture_default_str();
  vp->add_option("--scenario", args.scenario, "Scenario whose victoria_park filter and ekf2d sensor model apply")
      ->capture_default_str();
  vp->add_flag("--gzip", args.gzip, "gzip-compress the rawlog");
  vp->add_flag("--quiet,-q", args.quiet, "Print nothing but errors");
}

int run_convert_victoria_park(const ConvertVictoriaParkArgs& args) {
  const LoadedScenario loaded = load_checked(args.scenario, {"victoria_park.window=" + args.window});
  const VictoriaParkLog log = read_log(args.data);
  const std::vector<LaserScan> scans = scans_in(log, parse_scan_window(args.window, "--window"), "--window");
  const VictoriaParkStream stream(log, loaded.scenario);
  RawlogWriter writer(args.out, stream.sensor(), args.gzip);
  for (std::size_t i = 0; i < scans.size(); ++i)
    writer.write(stream.frame(scans, i), {}, kSimulationEpoch_s + scans[i].time);
  writer.close();
  if (!args.quiet)
    std::printf("wrote %s: %zu scans (%d to %d)\n", args.out.c_str(), scans.size(), scans.front().index,
                scans.back().index);
  return 0;
}

}  // namespace relslam::eval
