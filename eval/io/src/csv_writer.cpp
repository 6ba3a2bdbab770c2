#include "relslam/eval/io/csv_writer.hpp"

namespace relslam::eval {

CsvWriter::CsvWriter(const std::filesystem::path& path, std::vector<std::string> columns)
    : file_(path), columns_(std::move(columns)) {
  std::string& out = file_.buffer();
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (i) out += ',';
    append_text(out, columns_[i]);
  }
  out += '\n';
}

void CsvWriter::check_width(std::size_t fields) const {
  if (fields != columns_.size())
    throw std::logic_error(file_.path().string() + ": row has " + std::to_string(fields) + " fields for " +
                           std::to_string(columns_.size()) + " columns");
}

void CsvWriter::row_fields(const std::vector<CsvField>& fields) {
  check_width(fields.size());
  std::string& out = file_.buffer();
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) out += ',';
    append_field(out, fields[i]);
  }
  out += '\n';
  file_.maybe_flush();
}

void CsvWriter::row_fields(const std::vector<std::string>& texts, const std::vector<std::optional<double>>& numbers) {
  check_width(texts.size() + numbers.size());
  std::string& out = file_.buffer();
  bool first = true;
  for (const std::string& t : texts) {
    out += first ? "" : ",";
    first = false;
    append_text(out, t);
  }
  for (const std::optional<double>& v : numbers) {
    out += first ? "" : ",";
    first = false;
    append_field(out, v);
  }
  out += '\n';
  file_.maybe_flush();
}

// RFC 4180 quoting, only when needed.
void CsvWriter::append_text(std::string& out, std::string_view text) {
  if (text.find_first_of(",\"\n\r") == std::string_view::npos) {
    out += text;
    return;
  }
  out += '"';
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
}

}  // namespace relslam::eval
