#pragma once
// Reading back the CSV files CsvWriter writes (RFC 4180 quoting), so tables that summarize
// run folders can be rebuilt from the folders alone (relslam sweep --aggregate).

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace relslam::eval {

struct CsvContents {
  std::filesystem::path file;  // for messages
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  // each as wide as the header
  std::vector<int> lines;                      // 1-based text line where each row starts

  // Index of a column, or -1.
  int column(std::string_view name) const;
};

// Throws InputError (file:line) when the file cannot be read, a quote is left open or a row's
// width differs from the header's.
CsvContents read_csv_table(const std::filesystem::path& file);

}  // namespace relslam::eval
