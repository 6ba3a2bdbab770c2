#pragma once
// iterations.csv of every algorithm: the same score columns first, so runs of different
// algorithms plot and compare column by column, then the algorithm's own diagnostics.

#include "relslam/eval/csv_writer.hpp"
#include "relslam/eval/run_scorer.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace relslam::eval {

class IterationTable {
 public:
  // Shared columns: iteration, landmark_error, mean_landmark_error, position_error, ex, ey, ez,
  // runtime_ms, landmarks_in_map, visible_points; then `own_columns`.
  IterationTable(const std::filesystem::path& file, const std::vector<std::string>& own_columns);

  template <class... Own>
  void row(int iteration, const IterationScore& s, double runtime_ms, std::size_t visible_points, const Own&... own) {
    csv_.row(iteration, s.landmark_error, s.mean_landmark_error, s.position_error, s.axis_error.x(), s.axis_error.y(),
             s.axis_error.z(), runtime_ms, s.landmarks_on_map, visible_points, own...);
  }
  void close() { csv_.close(); }

 private:
  CsvWriter csv_;
};

}  // namespace relslam::eval
