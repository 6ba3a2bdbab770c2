#include "relslam/eval/io/csv_reader.hpp"

#include "relslam/eval/config/input_error.hpp"

#include <fstream>
#include <sstream>

namespace relslam::eval {

int CsvContents::column(std::string_view name) const {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return static_cast<int>(i);
  return -1;
}

CsvContents read_csv_table(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), 0, "", "cannot read the file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();

  CsvContents table{file, {}, {}, {}};
  std::vector<std::string> record;
  std::string field;
  int line = 1, record_line = 1;
  bool quoted = false, any = false;
  auto end_record = [&] {
    record.push_back(field);
    field.clear();
    if (!any) {
      table.header = record;
      any = true;
    } else {
      if (record.size() != table.header.size())
        throw InputError(file.string(), record_line, "",
                         "row has " + std::to_string(record.size()) + " fields for " +
                             std::to_string(table.header.size()) + " columns");
      table.rows.push_back(record);
      table.lines.push_back(record_line);
    }
    record.clear();
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        if (c == '\n') ++line;
        field += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      record.push_back(field);
      field.clear();
    } else if (c == '\r' && (i + 1 == text.size() || text[i + 1] == '\n')) {
      // CRLF line ends (and a last line's CR) are line ends, outside quotes only: a quoted CR
      // is the field's, as CsvWriter writes it.
    } else if (c == '\n') {
      end_record();
      record_line = ++line;
    } else {
      field += c;
    }
  }
  if (quoted) throw InputError(file.string(), record_line, "", "a quoted field is not closed");
  if (!field.empty() || !record.empty()) end_record();
  if (!any) throw InputError(file.string(), 1, "", "empty file: expected a header row");
  return table;
}

}  // namespace relslam::eval
