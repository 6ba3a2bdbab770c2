// Victoria Park timing (thesis 6.8): the Relative Point algorithm's time per scan with
// one grouping level, two (with dynamic-point detection) and three, on the thesis's windows and
// the whole log (7,249 scans, bridged by dead reckoning). The thesis measured 0.296 / 0.40 /
// 0.57 ms per scan, 2.15 / 2.9 / 4.13 s for the log, on a 2004 CPU; our target is the whole
// log under 0.3 s. Needs the data: $RELSLAM_VICTORIA_PARK or ../shared/datasets/victoria_park.
#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/victoria_park_experiment.hpp"
#include "relslam/point/rlt_mapper.hpp"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <optional>

namespace {

using namespace relslam;

const std::optional<eval::VictoriaParkLog>& data() {
  static const std::optional<eval::VictoriaParkLog> log = [] {
    std::filesystem::path dir = eval::victoria_park_dir();
    if (!std::filesystem::exists(dir / "measurements.dat"))
      dir = std::filesystem::path(RELSLAM_SOURCE_DIR) / "../shared/datasets/victoria_park";
    return std::filesystem::exists(dir / "measurements.dat") ? std::optional(eval::read_victoria_park(dir))
                                                             : std::nullopt;
  }();
  return log;
}

// The grouping levels: 1 = final groups only, no binning; 2 = temporary and final groups with
// dynamic-point detection (the scenario); 3 = and level 3.
eval::LoadedScenario configured(int levels, const std::string& window) {
  std::vector<std::string> set = {"victoria_park.window=" + window};
  if (window == "all") set.push_back("relative_point.use_odometry=true");
  if (levels == 1)
    set.insert(set.end(), {"relative_point.temporary_group.enabled=false", "relative_point.final_group.binning=false"});
  if (levels == 3) set.push_back("relative_point.level3.enabled=true");
  return eval::load_with_overrides(std::string(RELSLAM_SOURCE_DIR) + "/scenarios/victoria-park.json", set);
}

void BM_VictoriaParkLevels(benchmark::State& state) {
  if (!data()) {
    state.SkipWithError("Victoria Park data not found: set RELSLAM_VICTORIA_PARK");
    return;
  }
  static const char* windows[] = {"1181:1642", "4220:4634", "all"};
  const std::string window = windows[state.range(1)];
  const eval::LoadedScenario loaded = configured(static_cast<int>(state.range(0)), window);
  const auto scans = eval::scans_in(*data(), eval::parse_scan_window(window, "window"), "window");
  const eval::VictoriaParkStream stream(*data(), loaded.scenario);
  std::vector<ObservationFrame> frames;
  for (std::size_t i = 0; i < scans.size(); ++i) frames.push_back(stream.frame(scans, i));
  double seconds = 0;
  std::size_t mapped = 0;
  for (auto _ : state) {
    point::RltMapper mapper(loaded.scenario.relative_point);
    const auto start = std::chrono::steady_clock::now();
    for (const ObservationFrame& f : frames) mapper.step(f);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    mapped = 0;
    for (const auto& p : mapper.points()) mapped += p.on_map();
  }
  state.SetLabel("levels " + std::to_string(state.range(0)) + ", window " + window);
  state.counters["scans"] = static_cast<double>(frames.size());
  state.counters["ms_per_scan"] = 1e3 * seconds / static_cast<double>(frames.size());
  state.counters["s_per_7249"] = seconds / static_cast<double>(frames.size()) * 7249.0;
  state.counters["mapped"] = static_cast<double>(mapped);
}
BENCHMARK(BM_VictoriaParkLevels)->ArgsProduct({{1, 2, 3}, {0, 1, 2}})->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
