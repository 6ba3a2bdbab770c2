#include "test_support.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace relslam {
namespace {

TEST(BenchBinningCommand, WritesEveryBinningAndTheMeansPerCell) {
  test::ScratchDir dir;
  const auto r = test::run_relslam({"bench-binning", test::source_path("scenarios/s-bin.json").string(), "--out",
                                    (dir / "bin").string(), "-q", "--set", "binning_bench.points=[20,40]", "--set",
                                    "binning_bench.percentages=[0,10,50]", "--set", "binning_bench.seeds=2"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = test::read_lines(dir / "bin/binning_bench.csv");
  // 2 pairings x 2 heuristic settings x 2 sizes x 2 seeds x (3 shares + the correlated mix).
  EXPECT_EQ(rows.size(), 1u + 2 * 2 * 2 * 2 * 4);
  EXPECT_EQ(rows[0],
            "n,percent,variant,pairing,heuristic,seed,comparisons,highest_bin,threshold,wrongly_flagged,missed");
  int zero_percent = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    std::stringstream in(rows[i]);
    std::vector<std::string> f;
    for (std::string s; std::getline(in, s, ',');) f.push_back(s);
    if (f[1] == "0" && f[3] == "disjoint") {
      ++zero_percent;
      EXPECT_EQ(std::stoi(f[6]), std::stoi(f[0]) - 1) << "all static: n - 1 comparisons (" << rows[i] << ")";
      EXPECT_EQ(f[7], f[0]) << "all in one bin";
    }
  }
  EXPECT_EQ(zero_percent, 8);
  EXPECT_EQ(test::read_lines(dir / "bin/binning_bench_means.csv").size(), 1u + 2 * 2 * 2 * 4);
}

TEST(BenchBinningCommand, RefusesASimulationScenario) {
  test::ScratchDir dir;
  const auto r = test::run_relslam(
      {"bench-binning", test::source_path("scenarios/s-f8.json").string(), "--out", (dir / "x").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bench-binning needs a scenario of kind binning_benchmark"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace relslam
