#include "relslam/eval/cli/commands/simulate.hpp"

#include "relslam/eval/config/scenario_half.hpp"
#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/interruption.hpp"
#include "relslam/eval/io/progress.hpp"
#include "relslam/eval/io/run_folder.hpp"
#include "relslam/eval/sources/planar_simulation_source.hpp"
#include "relslam/eval/sources/simulation_source.hpp"

#include <chrono>
#include <cstdio>

namespace relslam::eval {

void add_simulate(CLI::App& app, SimulateArgs& args) {
  add_scenario_command(app, args, "simulate", "Simulate a scenario and write ground truth and observations",
                       "Simulate a scenario: the robot follows its path, sees the noisy landmarks inside its frustum,\n"
                       "and everything is written to one run folder: ground_truth_path.tum (evo reads it),\n"
                       "ground_truth_landmarks.csv, sim_iterations.csv, observations.csv, observations.rawlog (MRPT)\n"
                       "and manifest.json. A planar scenario (kind \"planar\": walls, thesis Chapter 4) writes\n"
                       "ground_truth_walls.csv, ground_truth_path.tum, plane_observations.csv and manifest.json; with\n"
                       "planar.sensor \"laser\" also laser.rawlog (2-D scans with odometry, for MRPT's icp-slam),\n"
                       "with \"depth\" depth.rawlog (every planar.depth_record_every-th 640x480 depth image).\n"
                       "The same scenario and seed always give the same bytes.",
                       "scenarios/s-f8.json");
}

namespace {

// Runs `stream` (the frame loop); true when a signal stopped it. Any other error finishes the
// manifest as failed before it reaches main.
template <class Stream>
bool stream_until_interrupted(const SimulateArgs& args, const Scenario& scenario, const Invocation& invocation,
                              const Stream& stream) {
  try {
    stream();
    return false;
  } catch (const RunInterrupted&) {
    std::fprintf(stderr, "relslam: interrupted; %s holds the iterations simulated\n", args.out.c_str());
    return true;
  } catch (const std::exception& e) {
    record_failure(args.out, scenario, invocation, e);
    throw;
  }
}

// What both worlds do: the folder, the manifest as "running", the frames recorded into the
// folder as they pass, then the manifest finished. `extra(seconds)` gives the manifest's entries
// and `report(seconds)` prints the summary. Returns the exit status.
template <class Source, class Extra, class Report>
int simulate_into(const SimulateArgs& args, const LoadedScenario& loaded, const std::vector<std::string>& command_line,
                  Source& source, const Extra& extra, const Report& report) {
  const Scenario& scenario = loaded.scenario;
  prepare_run_folder(args.out, args.force);
  const Invocation invocation{"simulate", command_line, args.scenario, args.set};
  catch_interrupts();  // before the manifest says running: a signal from then on is seen
  write_manifest(args.out, scenario, invocation, {}, kRunStatusRunning);
  source.record_into(args.out);
  const auto start = std::chrono::steady_clock::now();
  Progress progress("simulate " + scenario.name, source.frames(), !args.quiet);
  const bool interrupted = stream_until_interrupted(args, scenario, invocation, [&] {
    source.stream([&](const auto& observation, const auto&...) {
      stop_if_interrupted();
      progress.update(observation.iteration + 1);
    });
  });
  progress.finish();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_manifest(args.out, scenario, invocation, extra(seconds), interrupted ? kRunStatusInterrupted : kRunStatusOk);
  if (interrupted) return kInterruptedExit;
  if (!args.quiet) report(seconds);
  return 0;
}

}  // namespace

int run_simulate(const SimulateArgs& args, const std::vector<std::string>& command_line) {
  const LoadedScenario loaded = load_checked(args.scenario, args.set);
  const Scenario& scenario = loaded.scenario;
  // Each world is built (and checked) before the folder is touched.
  if (feeds_planes(scenario.kind)) {  // walls, path and plane observations
    PlanarSimulationSource source(loaded);
    return simulate_into(
        args, loaded, command_line, source,
        [&](double seconds) {
          nlohmann::json extra = source.describe();
          extra["wall_time_s"] = seconds;
          return extra;
        },
        [&](double seconds) {
          const PlanarSimulationSummary& s = source.summary();
          std::printf("simulated %s (%s): %d iterations, %d walls, %.1f units travelled\n", scenario.name.c_str(),
                      source.map().name.c_str(), s.iterations, s.walls, s.distance_travelled);
          std::printf("planes seen per iteration: mean %.2f, min %d, max %d\n", s.visible_mean, s.visible_min,
                      s.visible_max);
          std::printf("wrote %s in %.2f s\n", args.out.c_str(), seconds);
        });
  }
  SimulationSource source(loaded);
  return simulate_into(
      args, loaded, command_line, source,
      [&](double seconds) {
        const SimulationSummary& summary = source.summary();
        return nlohmann::json{{"simulation_summary",
                               {{"iterations", summary.iterations},
                                {"landmarks", summary.landmarks},
                                {"dynamic_landmarks", summary.dynamic_landmarks},
                                {"detections", summary.detections},
                                {"visible_mean", summary.visible_mean},
                                {"visible_min", summary.visible_min},
                                {"visible_max", summary.visible_max},
                                {"distance_travelled", summary.distance_travelled},
                                {"wall_time_s", seconds}}}};
      },
      [&](double seconds) {
        const SimulationSummary& summary = source.summary();
        std::printf("simulated %s: %d iterations, %d landmarks (%d dynamic), %.1f units travelled\n",
                    scenario.name.c_str(), summary.iterations, summary.landmarks, summary.dynamic_landmarks,
                    summary.distance_travelled);
        std::printf("visible per iteration: mean %.1f, min %d, max %d (density %g)\n", summary.visible_mean,
                    summary.visible_min, summary.visible_max, scenario.sim.density);
        std::printf("wrote %s in %.2f s\n", args.out.c_str(), seconds);
      });
}

}  // namespace relslam::eval
