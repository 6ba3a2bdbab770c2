#include "relslam/eval/experiments/iteration_table.hpp"

namespace relslam::eval {
namespace {

std::vector<std::string> with_score_columns(const std::vector<std::string>& own) {
  std::vector<std::string> columns = {
      "iteration", "landmark_error", "mean_landmark_error", "position_error", "ex", "ey",
      "ez",        "runtime_ms",     "landmarks_in_map",    "visible_points"};
  columns.insert(columns.end(), own.begin(), own.end());
  return columns;
}

}  // namespace

IterationTable::IterationTable(const std::filesystem::path& file, const std::vector<std::string>& own_columns)
    : csv_(file, with_score_columns(own_columns)) {}

void IterationTable::row(int iteration, const IterationScore& s, double runtime_ms, std::size_t visible_points,
                         const std::vector<CsvField>& own) {
  fields_ = {csv_field(iteration),        csv_field(s.landmark_error), csv_field(s.mean_landmark_error),
             csv_field(s.position_error), csv_field(s.axis_error.x()), csv_field(s.axis_error.y()),
             csv_field(s.axis_error.z()), csv_field(runtime_ms),       csv_field(s.landmarks_on_map),
             csv_field(visible_points)};
  fields_.insert(fields_.end(), own.begin(), own.end());
  csv_.row_fields(fields_);
}

}  // namespace relslam::eval
