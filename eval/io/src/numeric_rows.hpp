#pragma once
// Whitespace-separated numeric text files (MRPT's ground truth, the Victoria Park ASCII data):
// one data row per line, '%' and '#' start comment lines. Internal to eval/.

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace relslam::eval {

struct NumericRow {
  int line = 0;                // 1-based text line, for error messages
  std::vector<double> values;  // every one finite
};

// Every data row of `file`. Throws InputError naming the file (and line) when the file is
// missing, a field is not a finite number, a row has fewer than `min_columns` numbers, or there
// is no data row at all. `columns_hint` describes the expected row in that message.
std::vector<NumericRow> read_numeric_rows(const std::filesystem::path& file, std::size_t min_columns,
                                          const char* columns_hint);
// The same from text already read; `name` stands for the file in messages.
std::vector<NumericRow> parse_numeric_rows(std::string_view text, const std::string& name, std::size_t min_columns,
                                           const char* columns_hint);

}  // namespace relslam::eval
