#pragma once
// An adapter's own CSV columns as a table of named readers, so header and fields cannot drift
// apart: one entry per column, its name and how to read it off a row.

#include "relslam/eval/io/csv_writer.hpp"

#include <string>
#include <vector>

namespace relslam::eval {

// A column of a table bound by name: the header text and how to read the field off a row.
template <class Row>
struct Column {
  const char* name;
  CsvField (*read)(const Row&);
};
template <class Row>
using Columns = std::vector<Column<Row>>;

template <class Row>
std::vector<std::string> column_names(const Columns<Row>& columns) {
  std::vector<std::string> names;
  for (const Column<Row>& c : columns) names.emplace_back(c.name);
  return names;
}
template <class Row>
void append_fields(const Columns<Row>& columns, const Row& row, std::vector<CsvField>& out) {
  for (const Column<Row>& c : columns) out.push_back(c.read(row));
}

}  // namespace relslam::eval
