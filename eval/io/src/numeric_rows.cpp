#include "numeric_rows.hpp"

#include "relslam/eval/config/input_error.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>

namespace relslam::eval {

std::vector<NumericRow> read_numeric_rows(const std::filesystem::path& file, std::size_t min_columns,
                                          const char* columns_hint) {
  if (!std::filesystem::exists(file)) throw InputError(file.string(), 0, "", "file not found");
  std::ifstream in(file);
  std::vector<NumericRow> rows;
  int line_number = 0;
  std::string line;
  while (std::getline(in, line)) {
    ++line_number;
    const std::size_t start = line.find_first_not_of(" \t\r");
    if (start == std::string::npos || line[start] == '%' || line[start] == '#') continue;
    NumericRow row{line_number, {}};
    const char* p = line.c_str() + start;
    while (*p) {
      char* end = nullptr;
      const double v = std::strtod(p, &end);
      const char* field_end = p;
      while (*field_end && *field_end != ' ' && *field_end != '\t' && *field_end != '\r') ++field_end;
      if (end != field_end || !std::isfinite(v))
        throw InputError(file.string(), line_number, "", "not a finite number: \"" + std::string(p, field_end) + "\"");
      row.values.push_back(v);
      p = field_end;
      while (*p == ' ' || *p == '\t' || *p == '\r') ++p;
    }
    if (row.values.size() < min_columns)
      throw InputError(
          file.string(), line_number, "",
          std::string("expected ") + columns_hint + ", got " + std::to_string(row.values.size()) + " numbers");
    rows.push_back(std::move(row));
  }
  if (rows.empty()) throw InputError(file.string(), 0, "", "no data rows");
  return rows;
}

}  // namespace relslam::eval
