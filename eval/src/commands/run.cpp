#include "relslam/eval/commands/run.hpp"

#include "relslam/eval/algorithm_run.hpp"
#include "relslam/eval/frame_stream.hpp"
#include "relslam/eval/progress.hpp"
#include "relslam/eval/run_folder.hpp"
#include "relslam/eval/scenario_loading.hpp"
#include "relslam/eval/simulation_recorder.hpp"

#include <chrono>
#include <cstdio>

namespace relslam::eval {

void add_run(CLI::App& app, RunArgs& args) {
  add_scenario_command(
      app, args, "run", "Simulate a scenario and run its algorithms on the same observations",
      "Simulate a scenario and feed every frame to each algorithm the scenario lists (key `algorithms`),\n"
      "scoring them against the truth as they go. Writes the simulation files of `relslam simulate`, one\n"
      "folder per algorithm (iterations.csv, landmarks.csv, trajectory.tum) and summary.csv.",
      "scenarios/s-f8.json");
}

int run_run(const RunArgs& args, const std::vector<std::string>& command_line) {
  const LoadedScenario loaded = load_with_overrides(args.scenario, args.set);
  const Scenario& scenario = loaded.scenario;
  if (scenario.algorithms.empty())
    throw loaded.error("algorithms", "the scenario lists no algorithm to run; add one, e.g. --set algorithms=relative_point");
  const sim::Simulator simulator = build_simulator(loaded);
  prepare_run_folder(args.out, args.force);

  const auto start = std::chrono::steady_clock::now();
  const LandmarkTruth truth = landmark_truth(simulator.world());
  SimulationRecorder recorder(args.out, scenario, simulator);
  std::vector<std::unique_ptr<AlgorithmRun>> runs;
  for (const std::string& name : scenario.algorithms) runs.push_back(make_algorithm_run(name, scenario, truth, args.out));

  Progress progress("run " + scenario.name, simulator.iterations(), !args.quiet);
  stream_frames(simulator, [&](const sim::SimFrame& frame) {
    recorder.record(frame);
    for (auto& run : runs) run->step(frame.observation, frame.truth);
    progress.update(frame.observation.iteration + 1);
  });
  const SimulationSummary simulated = recorder.finish();
  std::vector<SummaryRow> rows;
  for (auto& run : runs) rows.push_back(run->finish());
  progress.finish();
  write_summary(std::filesystem::path(args.out) / "summary.csv", rows);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  nlohmann::json results = nlohmann::json::array();
  for (const SummaryRow& r : rows)
    results.push_back({{"algorithm", r.algorithm}, {"status", r.status}, {"final_mean_landmark_error", r.final_mean_landmark_error},
                       {"final_position_error", r.final_position_error}, {"runtime_median_ms", r.runtime.median_ms}});
  write_manifest(args.out, scenario, {"run", command_line, args.scenario, args.set},
                 {{"simulation_summary", {{"iterations", simulated.iterations}, {"landmarks", simulated.landmarks},
                                          {"visible_mean", simulated.visible_mean}}},
                  {"results", results},
                  {"wall_time_s", seconds}});
  if (!args.quiet) {
    std::printf("%s: %d iterations, %d landmarks, %.1f visible per iteration\n", scenario.name.c_str(), simulated.iterations,
                simulated.landmarks, simulated.visible_mean);
    std::printf("%-16s %-8s %12s %14s %12s %12s %10s\n", "algorithm", "status", "map points", "mean lm err", "pos err",
                "median ms", "p95 ms");
    for (const SummaryRow& r : rows)
      std::printf("%-16s %-8s %12d %14.4g %12.4g %12.4g %10.4g\n", r.algorithm.c_str(),
                  r.status.substr(0, r.status.find(':')).c_str(), r.landmarks_on_map, r.final_mean_landmark_error,
                  r.final_position_error, r.runtime.median_ms, r.runtime.p95_ms);
    for (const SummaryRow& r : rows)
      if (r.status != "ok") std::printf("%s %s\n", r.algorithm.c_str(), r.status.c_str());
    std::printf("wrote %s in %.1f s\n", args.out.c_str(), seconds);
  }
  return 0;
}

}  // namespace relslam::eval
