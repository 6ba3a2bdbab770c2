#include "relslam/eval/experiments/iteration_table.hpp"

namespace relslam::eval {
namespace {

std::vector<std::string> with_score_columns(const std::vector<std::string>& own) {
  std::vector<std::string> columns = column_names(point_iteration_columns());
  columns.insert(columns.end(), own.begin(), own.end());
  return columns;
}

}  // namespace

const std::vector<ScoreColumn<PointIterationRow>>& point_iteration_columns() {
  using R = PointIterationRow;
  static const std::vector<ScoreColumn<R>> columns = {
      {"iteration", "", "the frame's iteration k", [](const R& r) { return csv_field(r.iteration); }},
      {"landmark_error", "world", "sum over the map of each landmark's distance from its true landmark (thesis 6.1)",
       [](const R& r) { return csv_field(r.score.landmark_error); }},
      {"mean_landmark_error", "world", "landmark_error per landmark on the map",
       [](const R& r) { return csv_field(r.score.mean_landmark_error); }},
      {"position_error", "world", "distance of the estimated position from the true one",
       [](const R& r) { return csv_field(r.score.position_error); }},
      {"ex", "world", "estimate - truth, world x", [](const R& r) { return csv_field(r.score.axis_error.x()); }},
      {"ey", "world", "estimate - truth, world y", [](const R& r) { return csv_field(r.score.axis_error.y()); }},
      {"ez", "world", "estimate - truth, world z", [](const R& r) { return csv_field(r.score.axis_error.z()); }},
      {"runtime_ms", "ms", "wall-clock time of the algorithm's step", [](const R& r) { return csv_field(r.runtime_ms); }},
      {"landmarks_in_map", "", "landmarks on the map", [](const R& r) { return csv_field(r.score.landmarks_on_map); }},
      {"visible_points", "", "observations in the frame", [](const R& r) { return csv_field(r.visible_points); }},
  };
  return columns;
}

IterationTable::IterationTable(const std::filesystem::path& file, const std::vector<std::string>& own_columns)
    : csv_(file, with_score_columns(own_columns)) {}

void IterationTable::row(const PointIterationRow& shared, const std::vector<CsvField>& own) {
  fields_.clear();
  append_fields(point_iteration_columns(), shared, fields_);
  fields_.insert(fields_.end(), own.begin(), own.end());
  csv_.row_fields(fields_);
}

}  // namespace relslam::eval
