#pragma once
// The one CSV writer (style.md 2.8): a header row, commas, '.' decimals, shortest round-trip
// doubles, empty fields for missing values, no comment lines.

#include "relslam/eval/text_output.hpp"

#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace relslam::eval {

class CsvWriter {
 public:
  CsvWriter(const std::filesystem::path& path, std::vector<std::string> columns);

  // One row; the number of fields must equal the number of columns.
  template <class... Fields>
  void row(const Fields&... fields) {
    if (sizeof...(Fields) != columns_.size())
      throw std::logic_error(file_.path().string() + ": row has " + std::to_string(sizeof...(Fields)) +
                             " fields for " + std::to_string(columns_.size()) + " columns");
    std::string& out = file_.buffer();
    bool first = true;
    ((out += first ? "" : ",", first = false, append_field(out, fields)), ...);
    out += '\n';
    file_.maybe_flush();
  }
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
  template <class T>
  static void append_field(std::string& out, const std::optional<T>& v) {
    if (v) append_field(out, *v);
  }
  static void append_text(std::string& out, std::string_view text);

  TextFile file_;
  std::vector<std::string> columns_;
};

}  // namespace relslam::eval
