#pragma once
// What one run of a scenario's algorithms gave: the summary rows and what the observations were.
// Its own header because every kind of experiment (point, planar, Victoria Park) returns it and
// the batches and the command line read it; none of them should need another's header for it.

#include "relslam/eval/config/scenario_half.hpp"
#include "relslam/eval/metrics/run_summary.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <vector>

namespace relslam::eval {

struct ExperimentResult {
  // The family that ran (run_skeleton.hpp sets it from the family, which half_of chose): the
  // columns its rows are printed and tabulated in.
  ScenarioHalf half = ScenarioHalf::Points;
  std::vector<SummaryRow> rows;     // one per algorithm
  std::optional<SummaryRow> ratio;  // relative_point over ekf6d (or ekf2d), when both ran
  // Every other algorithm over batch_optimum ("<name>/batch_optimum"), when it ran: how far each
  // is from the accuracy floor.
  std::vector<SummaryRow> optimum_ratios;
  int iterations = 0;
  double seconds = 0;
  nlohmann::json source;  // what the observations were: manifest material
  // SIGINT or SIGTERM stopped the frames early: the rows cover the frames processed.
  bool interrupted = false;
};

}  // namespace relslam::eval
