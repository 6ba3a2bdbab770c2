// EM plane extraction per frame, EM1 against EM2 (thesis 3.5.4: "the second one executes about
// twice as fast"; relative_plane_em.md §4.7, issue 14 §6). Frames: the point sensor (σ_pt =
// 0.05, seed 1) along Map D's path (small frustum) and Map E's (large frustum), every 20th
// iteration of the first loop, simulated before the timed region. Each benchmark iteration
// extracts one frame (round robin), with the frame's own EM seed. Counters per frame: points,
// planes and EM iterations. Nothing is asserted: the numbers are read.
#include "relslam/em/em1.hpp"
#include "relslam/em/em2.hpp"
#include "relslam/em/em_random.hpp"
#include "relslam/em/plane_conversion.hpp"
#include "relslam/eval/io/planar_map_file.hpp"
#include "relslam/sim/planar_simulator.hpp"

#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <vector>

namespace {

using namespace relslam;

constexpr double kSigma = 0.05;

struct Frames {
  std::vector<PlanarPointFrame> frames;
  double mean_points = 0;
};

const Frames& frames_of(const std::string& file) {
  static std::map<std::string, Frames> cache;
  auto [it, fresh] = cache.try_emplace(file);
  if (!fresh) return it->second;
  const sim::PlanarMap map = eval::read_planar_map(std::filesystem::path(RELSLAM_SOURCE_DIR) / "scenarios/maps" / file);
  sim::PointSensorOptions points = sim::PointSensorOptions::matching(map.sensor);
  points.sigma = kSigma;
  const sim::PlanarSimulator simulator(map, 1, points);
  const int last = std::min(simulator.iterations(), 2000);
  double total = 0;
  for (int k = 0; k < last; k += 20) {
    it->second.frames.push_back(simulator.point_frame(k).observation);
    total += static_cast<double>(it->second.frames.back().points.size());
  }
  it->second.mean_points = total / static_cast<double>(it->second.frames.size());
  return it->second;
}

template <bool kBatch>
void extract(benchmark::State& state, const std::string& file) {
  const Frames& f = frames_of(file);
  const em::EmOptions options = em::EmOptions::for_point_sigma(kSigma);
  std::size_t i = 0;
  double planes = 0, frames = 0, iterations = 0;
  for (auto _ : state) {
    const PlanarPointFrame& frame = f.frames[i++ % f.frames.size()];
    const std::uint64_t seed = em::em_frame_seed(1, frame.iteration);
    const em::EmResult result = kBatch ? em::run_em1(frame.points, options, seed) : em::run_em2(frame.points, options, seed);
    const em::ExtractedPlanes out = em::to_plane_objects(result, options, frame.iteration);
    benchmark::DoNotOptimize(out);
    planes += static_cast<double>(out.frame.planes.size());
    iterations += result.iterations;
    ++frames;
  }
  state.counters["points_per_frame"] = f.mean_points;
  state.counters["planes_per_frame"] = planes / frames;
  state.counters["em_iterations"] = iterations / frames;
}

void em1_map_d(benchmark::State& state) { extract<true>(state, "d_office_loop.json"); }
void em2_map_d(benchmark::State& state) { extract<false>(state, "d_office_loop.json"); }
void em1_map_e(benchmark::State& state) { extract<true>(state, "e_motion_room.json"); }
void em2_map_e(benchmark::State& state) { extract<false>(state, "e_motion_room.json"); }

BENCHMARK(em1_map_d)->Unit(benchmark::kMillisecond);
BENCHMARK(em2_map_d)->Unit(benchmark::kMillisecond);
BENCHMARK(em1_map_e)->Unit(benchmark::kMillisecond);
BENCHMARK(em2_map_e)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
