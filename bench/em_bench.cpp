// EM plane extraction per frame, EM1 against EM2 (thesis 3.5.4: "the second one executes about
// twice as fast"; thesis 3.5.4). Frames: the point sensor (σ_pt =
// 0.05, seed 1) along Map D's path (small frustum) and Map E's (large frustum), every 20th
// iteration of the first loop, simulated before the timed region. Each benchmark iteration
// extracts one frame (round robin), with the frame's own EM seed. A third case, "panels",
// stands in for the thesis's test bench with many planes per frame (Fig. 55): 24 short walls
// (1.5 long) in a staggered field, seen from 12 headings with the large frustum. Counters per frame: points,
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

// The panel field: rows at x = 4, 7, ..., 19, panels every 2.5 in z, alternate rows shifted so
// the rows behind show through the gaps; all face −x (the robot at the origin).
const Frames& panel_frames() {
  static Frames f = [] {
    Frames out;
    sim::PlanarWorld world;
    int id = 0;
    for (int row = 0; row < 6; ++row)
      for (int column = 0; column < 4; ++column) {
        const double x = 4.0 + 3.0 * row, z = -5.0 + 2.5 * column + (row % 2) * 1.25;
        world.walls.push_back(sim::Wall::between(id++, {x, z}, {x, z + 1.5}));
      }
    sim::PointSensorOptions points;
    points.frustum = sim::ViewingFrustum::large();
    points.sigma = kSigma;
    const sim::PointSensor sensor(points, world, 1);
    double total = 0;
    for (int k = 0; k < 12; ++k) {
      out.frames.push_back(sensor.observe(PlanarPose::from(0, 0, (k - 6) * 0.04), k).observation);
      total += static_cast<double>(out.frames.back().points.size());
    }
    out.mean_points = total / static_cast<double>(out.frames.size());
    return out;
  }();
  return f;
}

template <bool kBatch>
void extract(benchmark::State& state, const std::string& file) {
  const Frames& f = file.empty() ? panel_frames() : frames_of(file);
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
void em1_panels(benchmark::State& state) { extract<true>(state, ""); }
void em2_panels(benchmark::State& state) { extract<false>(state, ""); }

BENCHMARK(em1_map_d)->Unit(benchmark::kMillisecond);
BENCHMARK(em2_map_d)->Unit(benchmark::kMillisecond);
BENCHMARK(em1_map_e)->Unit(benchmark::kMillisecond);
BENCHMARK(em2_map_e)->Unit(benchmark::kMillisecond);
BENCHMARK(em1_panels)->Unit(benchmark::kMillisecond);
BENCHMARK(em2_panels)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
