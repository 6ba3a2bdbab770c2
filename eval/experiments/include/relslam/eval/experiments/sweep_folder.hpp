#pragma once
// A sweep folder's cells read back from disk: which runs finished and what they scored, which
// did not and why. The tables of every sweep (run here, resumed, or run by another engine and
// gathered with --aggregate) are made from this reading alone, so a table never counts a run
// that did not finish, whatever stopped it and whenever.

#include "relslam/eval/experiments/batch.hpp"
#include "relslam/eval/experiments/sweep_plan.hpp"

#include <vector>

namespace relslam::eval {

// One cell as its folder holds it. BatchResult::error is empty only for a run whose manifest
// says "ok" and whose summary.csv is whole: one row per algorithm the manifest's scenario lists,
// each once. Otherwise it says why, for people: "not run", "killed while running",
// "interrupted at iteration 2240", "failed: ...", "damaged: summary.csv: ...".
BatchResult read_cell(const BatchJob& job);

// Whether read_cell found the cell's files damaged (bad input, not an unfinished run).
bool damaged(const BatchResult& cell);

// Every cell of the plan, in plan order.
std::vector<BatchResult> read_cells(const SweepPlan& plan);

// The jobs of the plan whose cell has not finished (read_cell says why): what --resume reruns.
std::vector<BatchJob> unfinished_jobs(const SweepPlan& plan);

}  // namespace relslam::eval
