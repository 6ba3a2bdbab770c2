#pragma once
// A sweep's tables: sweep.csv (every run and algorithm) and aggregate.csv (statistics over the
// seeds). One writer for the local sweep and for --aggregate over cells run elsewhere, so the
// two give the same bytes for the same runs.

#include "relslam/eval/experiments/batch.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace relslam::eval {

// The half the sweep's scenario feeds, as its runs recorded it (BatchResult::half, half_of the
// scenario's kind): every table below names its columns as that half's summary columns do
// (summary_column). The point half when no run got as far as loading the scenario.
ScenarioHalf sweep_half(const std::vector<BatchResult>& results);

// sweep.csv in `out`: one row per run and algorithm; a run that failed (BatchResult::error) as
// one row with status "error: ...".
void write_runs_table(const std::filesystem::path& out, const std::vector<GridAxis>& axes,
                      const std::vector<BatchResult>& results, ScenarioHalf half);

// Per combination and algorithm: how many runs were planned, the rows usable for statistics,
// and the seeds whose run is missing, failed or gave no usable row (so no mean hides them).
// A run that failed as a whole counts against every algorithm its combination's other runs
// report (every algorithm seen, if none of them got through).
struct SweepCell {
  std::vector<std::string> labels;
  std::string algorithm;
  int runs = 0;
  std::vector<const SummaryRow*> ok;  // point into the results
  std::vector<int> not_ok_seeds;
};
// In grid order (first appearance).
std::vector<SweepCell> sweep_cells(const std::vector<BatchResult>& results);

// Whether any run of the sweep is missing or failed as a whole (the sweep then exits 1).
bool any_run_failed(const std::vector<BatchResult>& results);

// aggregate.csv in `out`: per cell the mean, standard deviation and 95 % CI of each metric.
void write_aggregate(const std::filesystem::path& out, const std::vector<GridAxis>& axes,
                     const std::vector<SweepCell>& cells, ScenarioHalf half);

// The cells as a table on stdout.
void print_cells(const std::vector<GridAxis>& axes, const std::vector<SweepCell>& cells, ScenarioHalf half);

}  // namespace relslam::eval
