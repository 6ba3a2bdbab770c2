// Simulating one figure-eight loop (3800 iterations): target under 2 s at
// density 550 (~535 visible points per frame) including writing the rawlog, on 2 cores.
#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/sources/frame_stream.hpp"
#include "relslam/eval/sources/simulated_world.hpp"
#include "relslam/eval/sources/simulation_recorder.hpp"

#include <benchmark/benchmark.h>

#include <unistd.h>
#include <filesystem>

namespace {

using namespace relslam;

eval::Scenario loop_at(double density) {
  eval::Scenario s;
  s.sim.density = density;
  return s;
}

// Frames only: world building plus 3800 frames (noise, culling, shuffle), one thread.
void BM_SimulateLoop(benchmark::State& state) {
  const eval::Scenario s = loop_at(static_cast<double>(state.range(0)));
  long long detections = 0;
  for (auto _ : state) {
    const sim::Simulator simulator(s.sim, s.seed);
    for (int k = 0; k < simulator.iterations(); ++k)
      detections += static_cast<long long>(simulator.frame(k).observation.points.size());
  }
  state.counters["visible_per_frame"] =
      static_cast<double>(detections) / (3800.0 * static_cast<double>(state.iterations()));
}
BENCHMARK(BM_SimulateLoop)->Arg(25)->Arg(100)->Arg(550)->Unit(benchmark::kMillisecond)->Iterations(3);

// What `relslam simulate` does: frames simulated one block ahead on a second thread while
// the run folder is written. range(1): 1 = also write observations.csv.
void BM_SimulateAndWrite(benchmark::State& state) {
  eval::Scenario s = loop_at(static_cast<double>(state.range(0)));
  s.output.observations_csv = state.range(1) != 0;
  const auto dir = std::filesystem::temp_directory_path() / ("relslam-bench-" + std::to_string(getpid()));
  for (auto _ : state) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const sim::Simulator simulator(s.sim, s.seed);
    eval::SimulationRecorder recorder(dir, s, simulator);
    eval::stream_frames(simulator, [&](const sim::SimFrame& frame) { recorder.record(frame); });
    recorder.finish();
  }
  state.counters["rawlog_MB"] = static_cast<double>(std::filesystem::file_size(dir / "observations.rawlog")) / 1e6;
  std::filesystem::remove_all(dir);
}
BENCHMARK(BM_SimulateAndWrite)
    ->ArgsProduct({{25, 100, 550}, {0, 1}})
    ->ArgNames({"density", "csv"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
