#pragma once
// The one CSV writer: a header row, commas, '.' decimals, shortest round-trip
// doubles, empty fields for missing values, no comment lines.

#include "relslam/eval/io/text_output.hpp"

#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace relslam::eval {

// One field whose type is known only at run time (columns bound by name in a table):
// empty, integer, number, flag (written 1/0) or text.
using CsvField = std::variant<std::monostate, long long, double, bool, std::string>;

// The field of a value, written exactly as CsvWriter::row writes that value.
template <class T>
CsvField csv_field(const T& value) {
  if constexpr (std::is_same_v<T, bool>)
    return value;
  else if constexpr (std::is_integral_v<T>)
    return static_cast<long long>(value);
  else if constexpr (std::is_floating_point_v<T>)
    return static_cast<double>(value);
  else
    return std::string(value);
}
template <class T>
CsvField csv_field(const std::optional<T>& value) {
  return value ? csv_field(*value) : CsvField{};
}

class CsvWriter {
 public:
  CsvWriter(const std::filesystem::path& path, std::vector<std::string> columns);

  // One row; the number of fields must equal the number of columns.
  template <class... Fields>
  void row(const Fields&... fields) {
    check_width(sizeof...(Fields));
    std::string& out = file_.buffer();
    bool first = true;
    ((out += first ? "" : ",", first = false, append_field(out, fields)), ...);
    out += '\n';
    file_.maybe_flush();
  }
  // A row whose width is known only at run time (tables with caller-chosen label columns):
  // the text fields first, then the numbers; missing numbers are empty fields.
  void row_fields(const std::vector<std::string>& texts, const std::vector<std::optional<double>>& numbers);
  // A row of typed fields (tables of named columns); as wide as the header.
  void row_fields(const std::vector<CsvField>& fields);
  void close() { file_.close(); }

 private:
  static void append_field(std::string& out, double v) { append_number(out, v); }
  static void append_field(std::string& out, float v) { append_number(out, static_cast<double>(v)); }
  template <class Int, std::enable_if_t<std::is_integral_v<Int> && !std::is_same_v<Int, bool>, int> = 0>
  static void append_field(std::string& out, Int v) {
    append_number(out, static_cast<long long>(v));
  }
  static void append_field(std::string& out, bool v) { out += v ? '1' : '0'; }
  static void append_field(std::string& out, const std::string& v) { append_text(out, v); }
  static void append_field(std::string& out, const char* v) { append_text(out, v); }
  static void append_field(std::string& out, const CsvField& v) {
    std::visit(
        [&out](const auto& x) {
          if constexpr (!std::is_same_v<std::decay_t<decltype(x)>, std::monostate>) append_field(out, x);
        },
        v);
  }
  template <class T>
  static void append_field(std::string& out, const std::optional<T>& v) {
    if (v) append_field(out, *v);
  }
  static void append_text(std::string& out, std::string_view text);
  void check_width(std::size_t fields) const;

  TextFile file_;
  std::vector<std::string> columns_;
};

}  // namespace relslam::eval
