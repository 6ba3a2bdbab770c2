#include "relslam/eval/csv_writer.hpp"

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
