#include "relslam/eval/cli/commands/bench_binning.hpp"

#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/binning_bench.hpp"
#include "relslam/eval/io/run_folder.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>

namespace relslam::eval {

void add_bench_binning(CLI::App& app, BenchBinningArgs& args) {
  add_scenario_command(app, args, "bench-binning", "Run the synthetic RltBinning benchmark S-BIN (thesis Figs 111-116)",
                       "Bin synthetic points (static ones plus a share of uncorrelated movers, and Fig 114's mix of\n"
                       "correlated groups) and count the pairwise comparisons, for every grid cell of the scenario's\n"
                       "binning_bench keys, both pairing rules and with and without the priority heuristic. Writes\n"
                       "binning_bench.csv (one row per binning) and binning_bench_means.csv (means over seeds, with\n"
                       "the n-1, n ln n, n log2 n, 3n ln n and n^2/2 reference curves).",
                       "scenarios/s-bin.json");
}

int run_bench_binning(const BenchBinningArgs& args, const std::vector<std::string>& command_line) {
  const LoadedScenario loaded = load_checked(args.scenario, args.set);
  const Scenario& scenario = loaded.scenario;
  if (scenario.kind != ScenarioKind::BinningBenchmark)
    throw loaded.error("kind", "bench-binning needs a scenario of kind binning_benchmark (e.g. scenarios/s-bin.json)");
  prepare_run_folder(args.out, args.force);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<BinningBenchRow> rows = run_binning_bench(scenario.binning_bench, scenario.seed);
  write_binning_bench(args.out, rows);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_manifest(args.out, scenario, {"bench-binning", command_line, args.scenario, args.set},
                 {{"binnings", rows.size()}, {"wall_time_s", seconds}});
  if (!args.quiet) {
    // The headline of Figs 113 and 115: mean comparisons at the largest n, per share.
    const int n = scenario.binning_bench.points.back();
    std::map<std::pair<double, bool>, std::pair<double, int>> cells;
    for (const BinningBenchRow& r : rows)
      if (r.n == n && r.pairing == point::BinPairing::EveryBin && std::string(r.variant) == "uncorrelated") {
        auto& [sum, count] = cells[{r.percent, r.heuristic}];
        sum += r.comparisons, ++count;
      }
    std::printf("comparisons at n = %d (every_bin pairing; n ln n = %.0f, n^2/2 = %d)\n", n, n * std::log(n),
                n * n / 2);
    std::printf("%9s %14s %14s\n", "percent", "no heuristic", "heuristic");
    for (double p : scenario.binning_bench.percentages)
      std::printf("%8g%% %14.0f %14.0f\n", p, cells[{p, false}].first / cells[{p, false}].second,
                  cells[{p, true}].first / cells[{p, true}].second);
    std::printf("wrote %s in %.1f s (%zu binnings)\n", args.out.c_str(), seconds, rows.size());
  }
  return 0;
}

}  // namespace relslam::eval
