#include "relslam/eval/cli/commands/em_bench.hpp"

#include "relslam/eval/config/scenario_half.hpp"
#include "relslam/eval/experiments/em_bench.hpp"
#include "relslam/eval/experiments/em_compare.hpp"
#include "relslam/eval/io/run_folder.hpp"

#include <chrono>
#include <cstdio>
#include <map>
#include <tuple>

namespace relslam::eval {

void add_em_bench(CLI::App& app, EmBenchArgs& args) {
  CLI::App* command = add_scenario_command(
      app, args, "em-bench", "Run the plane-extraction test bench (E30, thesis Figs 55-61)",
      "Extract the planes of small scenes (random walls, two close parallel walls, a smaller wall\n"
      "attached to a larger one, a wall over a gap, a corner with the exclusivity cull on and off,\n"
      "inlier distances, EM1's assignment modes) with EM1, EM2 and the Open3D baseline, for several\n"
      "seeds, with the scenario's relative_plane.em / ransac settings and planar.noise.point_sigma.\n"
      "Writes bench.csv (one row per case, seed and extractor; SegComp at 0.8), and the walls,\n"
      "planes and points of every case in bench_planes.csv and bench_points.csv.\n"
      "With --compare (E29): the scenario's own point frames (planar.iterations of them) through\n"
      "every extractor in turn, one em_compare.csv row per frame (ms, planes and SegComp scores of\n"
      "each), e.g. relslam em-bench scenarios/p-em-compare-office.json --compare --out runs/e29-d",
      "scenarios/p-em-office-noise.json");
  command->add_option("--seeds", args.seeds, "seeds per case (from the scenario's seed on)")->check(CLI::Range(1, 1000));
  command->add_flag("--compare", args.compare,
                    "E29: every extractor on the scenario's identical point frames, into em_compare.csv");
}

namespace {

int run_em_compare_command(const LoadedScenario& loaded, const EmBenchArgs& args,
                           const std::vector<std::string>& command_line) {
  prepare_run_folder(args.out, args.force);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<EmCompareSummary> summary = run_em_compare(loaded, args.out);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  nlohmann::json extractors = nlohmann::json::array();
  for (const EmCompareSummary& s : summary)
    extractors.push_back({{"extractor", s.extractor}, {"frames", s.frames}, {"median_ms", s.median_ms},
                          {"mean_recall", s.mean_recall}, {"mean_precision", s.mean_precision},
                          {"mean_normal_error_deg", s.mean_normal_error_deg}});
  write_manifest(args.out, loaded.scenario, {"em-bench", command_line, args.scenario, args.set},
                 {{"em_compare", extractors}, {"wall_time_s", seconds}});
  if (!args.quiet) {
    std::printf("%-14s %7s %10s %7s %9s %10s\n", "extractor", "frames", "median ms", "recall", "precision",
                "normal err");
    for (const EmCompareSummary& s : summary)
      std::printf("%-14s %7d %10.3f %7.4f %9.4f %9.3f°\n", s.extractor.c_str(), s.frames, s.median_ms,
                  s.mean_recall, s.mean_precision, s.mean_normal_error_deg);
    std::printf("wrote %s/em_compare.csv in %.1f s\n", args.out.c_str(), seconds);
  }
  return 0;
}

}  // namespace

int run_em_bench_command(const EmBenchArgs& args, const std::vector<std::string>& command_line) {
  const LoadedScenario loaded = load_checked(args.scenario, args.set);
  const Scenario& scenario = loaded.scenario;
  if (!feeds_planes(scenario.kind))
    throw loaded.error("kind", "em-bench needs a scenario of kind planar (e.g. scenarios/p-em-office.json)");
  if (args.compare) return run_em_compare_command(loaded, args, command_line);
  prepare_run_folder(args.out, args.force);
  const auto start = std::chrono::steady_clock::now();
  const EmBenchResult result =
      run_em_bench(scenario.extraction, scenario.planar.noise.point_sigma, scenario.seed, args.seeds);
  const std::vector<EmBenchRow>& rows = result.rows;
  write_em_bench(args.out, result);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_manifest(args.out, scenario, {"em-bench", command_line, args.scenario, args.set},
                 {{"rows", rows.size()}, {"seeds", args.seeds}, {"wall_time_s", seconds}});
  if (!args.quiet) {
    // Mean recall and precision per case and extractor.
    std::map<std::tuple<std::string, std::string, std::string>, std::tuple<double, double, int>> means;
    for (const EmBenchRow& r : rows) {
      auto& [recall, precision, n] = means[{r.scene, r.variant, r.extractor}];
      recall += r.score.recall, precision += r.score.precision, ++n;
    }
    std::printf("%-18s %-22s %-14s %7s %9s\n", "scene", "variant", "extractor", "recall", "precision");
    for (const auto& [key, m] : means)
      std::printf("%-18s %-22s %-14s %7.3f %9.3f\n", std::get<0>(key).c_str(), std::get<1>(key).c_str(),
                  std::get<2>(key).c_str(), std::get<0>(m) / std::get<2>(m), std::get<1>(m) / std::get<2>(m));
    std::printf("wrote %s/bench.csv in %.1f s (%zu rows)\n", args.out.c_str(), seconds, rows.size());
  }
  return 0;
}

}  // namespace relslam::eval
