#include "numeric_rows.hpp"

#include "relslam/eval/config/input_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

namespace relslam::eval {

std::vector<NumericRow> read_numeric_rows(const std::filesystem::path& file, std::size_t min_columns,
                                          const char* columns_hint) {
  if (!std::filesystem::exists(file)) throw InputError(file.string(), 0, "", "file not found");
  std::ifstream in(file, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parse_numeric_rows(text, file.string(), min_columns, columns_hint);
}

std::vector<NumericRow> parse_numeric_rows(std::string_view text, const std::string& name, std::size_t min_columns,
                                           const char* columns_hint) {
  std::vector<NumericRow> rows;
  int line_number = 0;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t eol = std::min(text.find('\n', at), text.size());
    // strtod needs a terminated string; one line at a time keeps the copy small.
    const std::string line(text.substr(at, eol - at));
    at = eol + 1;
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
        throw InputError(name, line_number, "", "not a finite number: \"" + std::string(p, field_end) + "\"");
      row.values.push_back(v);
      p = field_end;
      while (*p == ' ' || *p == '\t' || *p == '\r') ++p;
    }
    if (row.values.size() < min_columns)
      throw InputError(
          name, line_number, "",
          std::string("expected ") + columns_hint + ", got " + std::to_string(row.values.size()) + " numbers");
    rows.push_back(std::move(row));
  }
  if (rows.empty()) throw InputError(name, 0, "", "no data rows");
  return rows;
}

}  // namespace relslam::eval
