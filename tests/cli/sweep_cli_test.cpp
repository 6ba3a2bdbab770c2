// relslam sweep and relslam tune-ekf: grids of runs, their folders and tables.
#include "test_support.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <map>

namespace relslam {
namespace {

using test::CsvTable;
using test::read_csv;
using test::run_relslam;

// Small, fast runs: 120 iterations at density 25, no observation files.
std::vector<std::string> small(std::vector<std::string> args) {
  for (const char* s : {"sim.iterations=120", "sim.density=25", "relative_point.final_group.prev_min=8",
                        "output.observations_csv=false", "output.rawlog=false"})
    args.insert(args.end(), {"--set", s});
  return args;
}

TEST(SweepCommand, TwoByTwoByTwoSeedsGivesEightRunsAndTheirStatistics) {
  test::ScratchDir dir;
  const auto r = run_relslam(small({"sweep", test::source_path("scenarios/s-f8.json").string(), "--out",
                                    (dir / "sweep").string(), "-q", "--param", "sim.noise_sigma=0.05,0.1", "--param",
                                    "relative_point.final_group.prev_min=8,10", "--seeds", "2", "--jobs", "2"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  int folders = 0;
  for (const char* sigma : {"0.05", "0.1"})
    for (const char* prev : {"8", "10"})
      for (const char* seed : {"seed-1", "seed-2"}) {
        const auto run = dir / "sweep" / (std::string("sim.noise_sigma=") + sigma) /
                         ("relative_point.final_group.prev_min=" + std::string(prev)) / seed;
        folders += std::filesystem::exists(run / "summary.csv") && std::filesystem::exists(run / "manifest.json") &&
                   std::filesystem::exists(run / "relative_point/iterations.csv");
      }
  EXPECT_EQ(folders, 8);

  const CsvTable runs = read_csv(dir / "sweep/sweep.csv");
  ASSERT_EQ(runs.rows.size(), 8u);
  const CsvTable aggregate = read_csv(dir / "sweep/aggregate.csv");
  ASSERT_EQ(aggregate.rows.size(), 4u);
  // Each cell's statistics are those of its two seeds' rows.
  for (std::size_t i = 0; i < aggregate.rows.size(); ++i) {
    std::vector<double> values;
    for (std::size_t j = 0; j < runs.rows.size(); ++j)
      if (runs.text(j, "sim.noise_sigma") == aggregate.text(i, "sim.noise_sigma") &&
          runs.text(j, "relative_point.final_group.prev_min") ==
              aggregate.text(i, "relative_point.final_group.prev_min")) {
        EXPECT_EQ(runs.text(j, "status"), "ok");
        values.push_back(runs.number(j, "final_mean_landmark_error"));
      }
    ASSERT_EQ(values.size(), 2u);
    EXPECT_EQ(aggregate.text(i, "runs"), "2");
    EXPECT_EQ(aggregate.text(i, "ok"), "2");
    EXPECT_DOUBLE_EQ(aggregate.number(i, "final_mean_landmark_error_mean"), (values[0] + values[1]) / 2);
    const double std = std::abs(values[0] - values[1]) / std::sqrt(2.0);
    EXPECT_NEAR(aggregate.number(i, "final_mean_landmark_error_std"), std, 1e-12);
    EXPECT_NEAR(aggregate.number(i, "final_mean_landmark_error_ci95"), 12.706 * std / std::sqrt(2.0), 1e-12);
  }
  // More noise, more error (averaged over seeds and the other parameter).
  double low = 0, high = 0;
  for (std::size_t i = 0; i < aggregate.rows.size(); ++i)
    (aggregate.text(i, "sim.noise_sigma") == "0.05" ? low : high) +=
        aggregate.number(i, "final_mean_landmark_error_mean");
  EXPECT_LT(low, high);
}

TEST(SweepCommand, ARunInASweepIsTheRunRelslamRunMakes) {
  test::ScratchDir dir;
  ASSERT_EQ(run_relslam(small({"sweep", test::source_path("scenarios/s-f8.json").string(), "--out",
                               (dir / "sweep").string(), "-q", "--param", "sim.noise_sigma=0.07", "--seeds", "2"}))
                .exit_code,
            0);
  ASSERT_EQ(run_relslam(small({"run", test::source_path("scenarios/s-f8.json").string(), "--out",
                               (dir / "run").string(), "-q", "--set", "sim.noise_sigma=0.07", "--set", "seed=2"}))
                .exit_code,
            0);
  const auto swept = dir / "sweep/sim.noise_sigma=0.07/seed-2";
  for (const char* file : {"relative_point/landmarks.csv", "relative_point/trajectory.tum", "ground_truth_path.tum"})
    EXPECT_EQ(test::read_file(swept / file), test::read_file(dir / "run" / file)) << file;
}

TEST(SweepCommand, ScenarioVariantsAreAnAxis) {
  test::ScratchDir dir;
  test::write_file(dir / "v.json", R"({"sim": {"path": "figure_eight"}, "algorithms": ["relative_point"],
    "variants": {"quiet": {"sim.noise_sigma": 0.01}, "loud": {"sim.noise_sigma": 0.2}}})");
  const auto r = run_relslam(small({"sweep", (dir / "v.json").string(), "--out", (dir / "sweep").string(), "-q"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "sweep/variant=quiet/seed-1/summary.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir / "sweep/variant=loud/seed-1/summary.csv"));
  const CsvTable aggregate = read_csv(dir / "sweep/aggregate.csv");
  ASSERT_EQ(aggregate.rows.size(), 2u);
  std::map<std::string, double> error;
  for (std::size_t i = 0; i < 2; ++i)
    error[aggregate.text(i, "variant")] = aggregate.number(i, "final_mean_landmark_error_mean");
  EXPECT_LT(error.at("quiet"), error.at("loud"));
}

TEST(SweepCommand, ABadValueFailsBeforeAnyRun) {
  test::ScratchDir dir;
  const auto r = run_relslam(small({"sweep", test::source_path("scenarios/s-f8.json").string(), "--out",
                                    (dir / "sweep").string(), "--param", "sim.density=25,lots"}));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("sim.density: expected a number, got \"lots\""), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "sweep"));
  const auto unknown = run_relslam(small({"sweep", test::source_path("scenarios/s-f8.json").string(), "--out",
                                          (dir / "sweep").string(), "--param", "sim.densty=25"}));
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("--param: sim.densty: unknown key"), std::string::npos) << unknown.err;
}

TEST(TuneEkfCommand, RanksTheTrialsAndRecordsTheBest) {
  test::ScratchDir dir;
  const auto r = run_relslam(
      small({"tune-ekf", test::source_path("scenarios/s-ekf-f8.json").string(), "--out", (dir / "tune").string(), "-q",
             "--std-range", "0.05,0.4", "--std-angle-deg", "0.5", "--q-scale", "1", "--iterations", "60"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const CsvTable tune = read_csv(dir / "tune/tune.csv");
  ASSERT_EQ(tune.rows.size(), 2u);
  EXPECT_LE(tune.number(0, "mean_landmark_error"), tune.number(1, "mean_landmark_error"));
  EXPECT_EQ(tune.text(0, "iterations"), "60");
  std::ifstream best_file(dir / "tune/best.json");
  const nlohmann::json best = nlohmann::json::parse(best_file);
  EXPECT_DOUBLE_EQ(best["ekf6d"]["std_range"].get<double>(), tune.number(0, "std_range"));
  EXPECT_EQ(best["ekf6d"]["std_yaw_deg"], 0.5);
  EXPECT_EQ(best["ekf6d"]["std_pitch_deg"], 0.5);
  std::ifstream manifest_file(dir / "tune/manifest.json");
  const nlohmann::json manifest = nlohmann::json::parse(manifest_file);
  EXPECT_EQ(manifest["tuning"]["best"], best);
  EXPECT_EQ(manifest["tuning"]["seed"], 1001);  // the scenario's seed + 1000: never an experiment's
}

}  // namespace
}  // namespace relslam
