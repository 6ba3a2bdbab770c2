#include "relslam/eval/iteration_table.hpp"

namespace relslam::eval {
namespace {

std::vector<std::string> with_score_columns(const std::vector<std::string>& own) {
  std::vector<std::string> columns = {"iteration",  "landmark_error",   "mean_landmark_error", "position_error", "ex", "ey",
                                      "ez",         "runtime_ms",       "landmarks_in_map",    "visible_points"};
  columns.insert(columns.end(), own.begin(), own.end());
  return columns;
}

}  // namespace

IterationTable::IterationTable(const std::filesystem::path& file, const std::vector<std::string>& own_columns)
    : csv_(file, with_score_columns(own_columns)) {}

}  // namespace relslam::eval
