// libFuzzer target: the generic CSV reader (read_csv_table; outside input reaches it through
// read_summary, i.e. relslam sweep --aggregate over run folders), over the input written to a
// file. Bad input must end in InputError, nothing else. An accepted table has rows as wide as
// its header, each with its starting line, and CsvWriter writes it back to text this reader
// reads to the same table (the round trip sweep --aggregate relies on).

#include "fuzz_support.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/csv_reader.hpp"
#include "relslam/eval/io/csv_writer.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace {

using relslam::fuzz::require;

void check_shape(const relslam::eval::CsvContents& table) {
  require(!table.header.empty(), "an accepted table has no header field");
  require(table.lines.size() == table.rows.size(), "not one line number per row");
  int previous = 1;  // the header's line
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    require(table.rows[i].size() == table.header.size(), "a row is not as wide as the header");
    require(table.lines[i] > previous, "row lines do not increase after the header");
    previous = table.lines[i];
  }
}

// The table as CsvWriter writes it.
void write(const relslam::eval::CsvContents& table, const std::filesystem::path& path) {
  relslam::eval::CsvWriter out(path, table.header);
  for (const auto& row : table.rows) out.row_fields(std::vector<relslam::eval::CsvField>(row.begin(), row.end()));
  out.close();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static relslam::fuzz::ScratchFile input(".csv"), written("-written.csv");
  relslam::eval::CsvContents table;
  try {
    table = relslam::eval::read_csv_table(input.write(relslam::fuzz::as_text(data, size)));
  } catch (const relslam::eval::InputError&) {
    return 0;
  }
  check_shape(table);
  write(table, written.path());
  try {
    const relslam::eval::CsvContents again = relslam::eval::read_csv_table(written.path());
    require(again.header == table.header && again.rows == table.rows, "CsvWriter's copy reads to another table");
  } catch (const relslam::eval::InputError& e) {
    relslam::fuzz::fail(std::string("CsvWriter's copy of an accepted table is rejected: ") + e.what());
  }
  return 0;
}
