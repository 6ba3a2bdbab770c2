// The global relaxation's solve (relslam/relax/ceres_relaxation.hpp) on synthetic loops
// of groups, the shape of a figure eight's chain: each point is seen by five consecutive groups,
// the last groups' by the first ones (the loop closure). Each group's relative map is exact,
// its start transform drifted a little more each group, to 1° and 0.5 units at the loop's end
// (the closure's gap, as a figure eight's first loop shows), and group 0 holds the frame. Printed: ms per solve and the
// solver's iterations, for 100 to 1600 groups (S-40 keeps about 450 alive).
//   build/bench/relslam_bench_relax
#include "relslam/relax/ceres_relaxation.hpp"

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <vector>

namespace {

using relslam::Rigid3;
using relslam::point::RelaxationProblem;

// `laps` times round the loop, `per_lap` groups a lap: group i sees points 2i .. 2i + 9 (mod
// 2 per_lap), so each point is in five consecutive groups of every lap, tied from the first of
// them (its owner) to the others, as build_relaxation's star does. Later laps tie groups far
// apart in the chain, as revisits do.
constexpr int kStep = 2;
constexpr int kSeen = 10;

RelaxationProblem drifted_loop(int per_lap, int laps) {
  const int groups = per_lap * laps;
  const int points = kStep * per_lap;
  const double radius = 0.5 * per_lap;  // about a unit between neighbours
  const auto world_point = [&](int m) {
    const double a = 2 * std::numbers::pi * m / points;
    return Eigen::Vector3d((radius + 1.5 * std::sin(1.7 * m)) * std::cos(a),
                           (radius + 1.5 * std::sin(1.7 * m)) * std::sin(a), 0.4 * (m % 3) - 0.4);
  };
  std::vector<Rigid3> truth;
  for (int i = 0; i < groups; ++i) {
    const double a = 2 * std::numbers::pi * (kStep * (i % per_lap) + kSeen / 2) / points;
    truth.push_back({relslam::rotation_about(Eigen::Vector3d::UnitZ(), a + std::numbers::pi / 2),
                     Eigen::Vector3d(radius * std::cos(a), radius * std::sin(a), 0)});
  }
  RelaxationProblem problem;
  for (int m = 0; m < points; ++m) {
    // The groups seeing point m: those with 2j <= m' < 2j + 10 for m' = m or m + points, j the
    // group's place in its lap.
    std::vector<int> seen_by;
    for (int i = 0; i < groups; ++i)
      for (const int mm : {m, m + points})
        if (const int j = i % per_lap; kStep * j <= mm && mm < kStep * j + kSeen) seen_by.push_back(i);
    const Eigen::Vector3d p = world_point(m);
    for (std::size_t g = 1; g < seen_by.size(); ++g)
      problem.ties.push_back(
          {seen_by[0], truth[seen_by[0]].inverse() * p, seen_by[g], truth[seen_by[g]].inverse() * p, 3.0});
  }
  for (int i = 0; i < groups; ++i) {
    const double share = static_cast<double>(i) / groups;
    const Rigid3 drift{relslam::rotation_about(Eigen::Vector3d::UnitZ(), share * std::numbers::pi / 180),
                       Eigen::Vector3d(0.5 * share, 0, 0)};
    problem.world_T_group.push_back(drift * truth[i]);
  }
  problem.fixed.assign(groups, false);
  problem.fixed[0] = true;
  return problem;
}

void BM_RelaxDriftedLoop(benchmark::State& state) {
  const RelaxationProblem start = drifted_loop(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  int iterations = 0;
  for (auto _ : state) {
    state.PauseTiming();
    RelaxationProblem problem = start;
    state.ResumeTiming();
    const relslam::point::RelaxationReport report = relslam::relax::solve_relaxation(problem);
    iterations = report.solver_iterations;
    benchmark::DoNotOptimize(problem.world_T_group.data());
  }
  state.counters["solver_iterations"] = iterations;
  state.counters["ties"] = static_cast<double>(start.ties.size());
}
// {groups a lap, laps}: 100 to 1600 groups in one lap, and 400 in two and four laps.
BENCHMARK(BM_RelaxDriftedLoop)
    ->Args({100, 1})
    ->Args({400, 1})
    ->Args({1600, 1})
    ->Args({200, 2})
    ->Args({100, 4})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
