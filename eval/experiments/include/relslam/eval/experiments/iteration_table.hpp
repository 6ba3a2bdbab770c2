#pragma once
// iterations.csv of every point-half algorithm: the same score columns first, so runs of
// different algorithms plot and compare column by column, then the algorithm's own diagnostics.

#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/metrics/run_scorer.hpp"
#include "relslam/eval/metrics/score_column.hpp"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace relslam::eval {

// What the shared columns of one iterations.csv row read.
struct PointIterationRow {
  int iteration = 0;
  IterationScore score;
  double runtime_ms = 0;
  std::size_t visible_points = 0;
};

// The shared columns: iteration, landmark_error, mean_landmark_error, position_error, ex, ey,
// ez, runtime_ms, landmarks_in_map, visible_points.
const std::vector<ScoreColumn<PointIterationRow>>& point_iteration_columns();

class IterationTable {
 public:
  // The shared columns, then `own_columns`.
  IterationTable(const std::filesystem::path& file, const std::vector<std::string>& own_columns);

  // One row: the shared columns, then the algorithm's own fields in its column order.
  void row(const PointIterationRow& shared, const std::vector<CsvField>& own);
  void close() { csv_.close(); }

 private:
  CsvWriter csv_;
  std::vector<CsvField> fields_;  // reused row buffer
};

}  // namespace relslam::eval
