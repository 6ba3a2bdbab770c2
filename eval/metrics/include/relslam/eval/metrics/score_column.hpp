#pragma once
// A scorer as a column of a table (iterations.csv, summary.csv): its name, its unit, how it is
// computed, and the function that reads it from what was scored. The recorder writes the
// columns in table order and the summary reads the same tables, so a column's name and its value
// are one entry, never two positional lists kept apart. Adding a column is one entry.

#include "relslam/eval/io/csv_writer.hpp"

#include <functional>
#include <string>
#include <vector>

namespace relslam::eval {

template <class Scored>
struct ScoreColumn {
  std::string name;
  std::string unit;  // "" for counts and names; "world" for the world's units (metres for recorded data)
  std::string how;   // how it is computed, for people (the docs' column list)
  std::function<CsvField(const Scored&)> field;
};

template <class Scored>
std::vector<std::string> column_names(const std::vector<ScoreColumn<Scored>>& columns) {
  std::vector<std::string> names;
  for (const ScoreColumn<Scored>& c : columns) names.push_back(c.name);
  return names;
}

// Appends one field per column, in table order.
template <class Scored>
void append_fields(const std::vector<ScoreColumn<Scored>>& columns, const Scored& scored, std::vector<CsvField>& out) {
  for (const ScoreColumn<Scored>& c : columns) out.push_back(c.field(scored));
}

}  // namespace relslam::eval
