#pragma once
// Helpers shared by the test programs: scratch folders, file reading, in-process CLI runs.

#include <filesystem>
#include <string>
#include <vector>

namespace relslam::test {

// A fresh empty folder under the system temp dir, removed when the object dies.
class ScratchDir {
 public:
  ScratchDir();
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

std::string read_file(const std::filesystem::path& path);
void write_file(const std::filesystem::path& path, const std::string& text);
std::vector<std::string> read_lines(const std::filesystem::path& path);
// A CSV file as text fields (no quoting support beyond what our writers need in tests).
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  // Index of a column; a missing column is a test failure (and index 0).
  int column(const std::string& name) const;
  const std::string& text(std::size_t row, const std::string& name) const { return rows.at(row).at(column(name)); }
  double number(std::size_t row, const std::string& name) const { return std::stod(text(row, name)); }
};
CsvTable read_csv(const std::filesystem::path& file);

// Path of a file in the source tree (RELSLAM_SOURCE_DIR is set by CMake).
std::filesystem::path source_path(const std::string& relative);

// The Victoria Park data: $RELSLAM_VICTORIA_PARK, else ../shared/datasets/victoria_park next
// to the source tree; empty when it is not there (tests then GTEST_SKIP with this message).
std::filesystem::path victoria_park_data();
constexpr const char* kNoVictoriaPark =
    "Victoria Park data not found: set RELSLAM_VICTORIA_PARK to the folder holding measurements.dat";

// Runs the relslam command line in-process; stdout and stderr are captured.
struct CliResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};
CliResult run_relslam(const std::vector<std::string>& arguments);

// `relslam run scenarios/<scenario> --out <out> -q --set <each of settings>`.
std::vector<std::string> scenario_run_args(const std::string& scenario, const std::filesystem::path& out,
                                           const std::vector<std::string>& settings);

}  // namespace relslam::test
