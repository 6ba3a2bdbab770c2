// The figures, printed: the share of run time spent binning at 3 % dynamic points
// (thesis: under 2 %, Fig 117), comparisons against n ln n at 10 % uncorrelated points
// (Fig 113), init and load time per local index at densities 100-550 (Figs 138-139, 144-145),
// and the incremental against the rebuilt global index over two loops (Fig 110).
#include "relslam/point/rlt_binning.hpp"
#include "relslam/point/rlt_mapper.hpp"
#include "relslam/sim/random.hpp"
#include "relslam/sim/simulator.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <numeric>

namespace {

using namespace relslam;

std::vector<ObservationFrame> frames_of(const sim::SimOptions& o, std::uint64_t seed = 1) {
  const sim::Simulator simulator(o, seed);
  std::vector<ObservationFrame> frames;
  for (int k = 0; k < simulator.iterations(); ++k) frames.push_back(simulator.frame(k).observation);
  return frames;
}

std::vector<point::StepTimings> timings_of(const std::vector<ObservationFrame>& frames,
                                           const point::PointSlamOptions& o) {
  point::RltMapper mapper(o);
  std::vector<point::StepTimings> t;
  for (const ObservationFrame& f : frames) t.push_back(mapper.step(f).timings);
  return t;
}

template <class F>
double mean_of(const std::vector<point::StepTimings>& t, F field) {
  double sum = 0;
  for (const auto& s : t) sum += field(s);
  return sum / static_cast<double>(t.size());
}

// S-DYN3 (3 % of the points move), binning on; Fig 117 compares it with S-F8, binning off.
void BM_BinningShareAtThreePercentDynamic(benchmark::State& state) {
  sim::SimOptions dyn3;
  dyn3.dynamic.fraction = 0.03;
  const auto with_movers = frames_of(dyn3), plain = frames_of(sim::SimOptions{});
  point::PointSlamOptions binning_off;
  binning_off.final_group.binning = false;
  std::vector<point::StepTimings> on, off;
  for (auto _ : state) {
    on = timings_of(with_movers, point::PointSlamOptions{});
    off = timings_of(plain, binning_off);
  }
  const double binning = mean_of(on, [](const auto& s) { return s.binning_ms; });
  const double total = mean_of(on, [](const auto& s) { return s.total_ms(); });
  state.counters["binning_ms"] = binning;
  state.counters["total_ms"] = total;
  state.counters["binning_share_pct"] = 100.0 * binning / total;
  state.counters["extra_vs_sf8_ms"] = total - mean_of(off, [](const auto& s) { return s.total_ms(); });
}
BENCHMARK(BM_BinningShareAtThreePercentDynamic)->Unit(benchmark::kMillisecond)->Iterations(1);

// Synthetic binning at 10 % uncorrelated points: comparisons against n ln n.
void BM_BinningComparisonsAtTenPercent(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  sim::RandomSequence rng(7, sim::Stream::Field);
  std::vector<point::ObservationRing> rings(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d base(rng.uniform(-50, 50), rng.uniform(-5, 5), rng.uniform(0, 100));
    const double sigma = (i * 7919) % 10 == 0 ? std::hypot(0.1, 1.0) : 0.1;  // every tenth point, spread out
    for (int t = 0; t < 60; ++t) {
      const double x = rng.gaussian(), y = rng.gaussian(), z = rng.gaussian();
      rings[i].push({base + sigma * Eigen::Vector3d(x, y, z), t});
    }
  }
  point::BinningOptions o;
  o.pairing = static_cast<point::BinPairing>(state.range(1));
  point::BinningResult r;
  for (auto _ : state)
    r = point::rlt_binning(
        n, [&](int i, int j) { return point::pair_distance_std(rings[i], rings[j], 0, 59, 5); }, o);
  state.counters["comparisons"] = r.comparisons;
  state.counters["n_ln_n"] = n * std::log(static_cast<double>(n));
  state.counters["ratio"] = r.comparisons / (n * std::log(static_cast<double>(n)));
}
BENCHMARK(BM_BinningComparisonsAtTenPercent)
    ->ArgsProduct({{50, 100, 200, 400, 800}, {0, 1}})
    ->ArgNames({"n", "every_bin"})
    ->Unit(benchmark::kMicrosecond);

// Init (candidates + building the index) and load (matching) per local index and density.
void BM_LocalIndex(benchmark::State& state) {
  sim::SimOptions o;
  o.density = static_cast<double>(state.range(0));
  const auto frames = frames_of(o);
  point::PointSlamOptions options;
  options.local_index = static_cast<spatial::LocalIndexKind>(state.range(1));
  if (state.range(2)) options.local_cell_size = 1.5;  // the thesis's "small quads"
  std::vector<point::StepTimings> t;
  for (auto _ : state) t = timings_of(frames, options);
  state.counters["init_ms"] = mean_of(t, [](const auto& s) { return s.init_ms; });
  state.counters["load_ms"] = mean_of(t, [](const auto& s) { return s.load_ms; });
  state.counters["total_ms"] = mean_of(t, [](const auto& s) { return s.total_ms(); });
}
BENCHMARK(BM_LocalIndex)
    ->ArgsProduct({{100, 250, 400, 550}, {0, 1, 2}, {0}})
    ->Args({100, 0, 1})
    ->Args({400, 0, 1})
    ->ArgNames({"density", "index", "small_quads"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// Fig 110: two loops, incremental against rebuilt global index; mean time of each and the
// mean difference in the first and second loop (the rebuilt one grows while points are added).
void BM_IncrementalVersusRebuiltGlobalIndex(benchmark::State& state) {
  sim::SimOptions o;
  o.loops = 2;
  const auto frames = frames_of(o);
  point::PointSlamOptions rebuilt;
  rebuilt.global_index = spatial::GlobalIndexKind::Rebuilt;
  std::vector<point::StepTimings> inc, reb;
  for (auto _ : state) {
    inc = timings_of(frames, point::PointSlamOptions{});
    reb = timings_of(frames, rebuilt);
  }
  auto mean_range = [](const std::vector<point::StepTimings>& t, std::size_t a, std::size_t b) {
    double s = 0;
    for (std::size_t k = a; k < b; ++k) s += t[k].total_ms();
    return s / static_cast<double>(b - a);
  };
  const std::size_t half = frames.size() / 2;
  state.counters["incremental_ms"] = mean_range(inc, 0, frames.size());
  state.counters["rebuilt_ms"] = mean_range(reb, 0, frames.size());
  state.counters["diff_loop1_ms"] = mean_range(inc, 0, half) - mean_range(reb, 0, half);
  state.counters["diff_loop2_ms"] = mean_range(inc, half, frames.size()) - mean_range(reb, half, frames.size());
  state.counters["rebuilt_init_last_100_ms"] =
      std::accumulate(reb.end() - 100, reb.end(), 0.0, [](double s, const auto& t) { return s + t.init_ms; }) / 100.0;
  state.counters["incremental_init_last_100_ms"] =
      std::accumulate(inc.end() - 100, inc.end(), 0.0, [](double s, const auto& t) { return s + t.init_ms; }) / 100.0;
}
BENCHMARK(BM_IncrementalVersusRebuiltGlobalIndex)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
