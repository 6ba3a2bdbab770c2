// aggregate.csv's cells: a run that is missing or failed stays visible in its
// combination's rows instead of vanishing from the statistics.

#include "relslam/eval/experiments/sweep_tables.hpp"

#include <gtest/gtest.h>

namespace relslam::eval {
namespace {

BatchResult run(const std::string& label, int seed, const std::vector<std::pair<std::string, bool>>& algorithms,
                const std::string& error = "") {
  BatchResult r{{"", {}, {label}, seed}, error, {}};
  for (const auto& [name, ok] : algorithms) {
    SummaryRow s;
    s.algorithm = name;
    s.status = ok ? RunStatus::ok() : RunStatus::failed(3, "diverged");
    r.rows.push_back(s);
  }
  return r;
}

TEST(SweepCells, AFailedRunCountsAgainstEveryAlgorithmOfItsCombination) {
  const std::vector<BatchResult> results = {run("a", 1, {{"rp", true}, {"ekf", true}}),
                                            run("a", 2, {}, "failed: the folder was in the way"),
                                            run("a", 3, {{"rp", true}, {"ekf", false}})};
  const std::vector<SweepCell> cells = sweep_cells(results);
  ASSERT_EQ(cells.size(), 2u);
  EXPECT_EQ(cells[0].algorithm, "rp");
  EXPECT_EQ(cells[0].runs, 3);
  EXPECT_EQ(cells[0].ok.size(), 2u);
  EXPECT_EQ(cells[0].not_ok_seeds, std::vector<int>({2}));
  EXPECT_EQ(cells[1].algorithm, "ekf");
  EXPECT_EQ(cells[1].ok.size(), 1u);
  EXPECT_EQ(cells[1].not_ok_seeds, std::vector<int>({2, 3})) << "the run that failed, then the algorithm that did";
  EXPECT_TRUE(any_run_failed(results));
}

TEST(SweepCells, ACombinationWhoseRunsAllFailedStillHasItsRows) {
  const std::vector<BatchResult> results = {run("a", 1, {{"rp", true}}), run("b", 1, {}, "not run (no folder)"),
                                            run("b", 2, {}, "not run (no folder)")};
  const std::vector<SweepCell> cells = sweep_cells(results);
  ASSERT_EQ(cells.size(), 2u);
  EXPECT_EQ(cells[1].labels, std::vector<std::string>({"b"}));
  EXPECT_EQ(cells[1].algorithm, "rp") << "the algorithms the other combinations report";
  EXPECT_EQ(cells[1].runs, 2);
  EXPECT_TRUE(cells[1].ok.empty());
  EXPECT_EQ(cells[1].not_ok_seeds, std::vector<int>({1, 2}));
}

TEST(SweepCells, ACompleteSweepHasNoFailedRun) {
  EXPECT_FALSE(any_run_failed({run("a", 1, {{"rp", true}}), run("a", 2, {{"rp", false}})}))
      << "an algorithm's failure is a result, not a failed run";
}

}  // namespace
}  // namespace relslam::eval
