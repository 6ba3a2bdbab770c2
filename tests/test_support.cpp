#include "test_support.hpp"

#include "relslam/eval/cli/app.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace relslam::test {

ScratchDir::ScratchDir() {
  static std::atomic<int> counter{0};
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "relslam";
  std::replace(name.begin(), name.end(), '/', '_');  // parameterised tests: "Prefix/Suite.Test/0"
  path_ = std::filesystem::temp_directory_path() /
          ("relslam-test-" + std::to_string(getpid()) + "-" + std::to_string(counter++) + "-" + name);
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

ScratchDir::~ScratchDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::vector<std::string> read_lines(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

namespace {

// Splits on commas, honouring RFC 4180 quotes.
std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

}  // namespace

int CsvTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return static_cast<int>(i);
  ADD_FAILURE() << "no column " << name;
  return 0;
}

CsvTable read_csv(const std::filesystem::path& file) {
  CsvTable t;
  const auto lines = read_lines(file);
  if (lines.empty()) {
    ADD_FAILURE() << file << " is empty or missing";
    return t;
  }
  t.header = split_csv(lines[0]);
  for (std::size_t i = 1; i < lines.size(); ++i) t.rows.push_back(split_csv(lines[i]));
  return t;
}

std::filesystem::path source_path(const std::string& relative) {
  return std::filesystem::path(RELSLAM_SOURCE_DIR) / relative;
}

std::filesystem::path victoria_park_data() {
  const char* env = std::getenv("RELSLAM_VICTORIA_PARK");
  const std::filesystem::path dir =
      env && *env ? std::filesystem::path(env) : source_path("../shared/datasets/victoria_park");
  return std::filesystem::exists(dir / "measurements.dat") ? dir : std::filesystem::path();
}

std::vector<std::string> scenario_run_args(const std::string& scenario, const std::filesystem::path& out,
                                           const std::vector<std::string>& settings) {
  std::vector<std::string> args = {"run", source_path("scenarios/" + scenario).string(), "--out", out.string(), "-q"};
  for (const std::string& s : settings) args.insert(args.end(), {"--set", s});
  return args;
}

CliResult run_relslam(const std::vector<std::string>& arguments) {
  std::vector<const char*> argv = {"relslam"};
  for (const std::string& a : arguments) argv.push_back(a.c_str());
  CliResult result;
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  result.exit_code = eval::run_cli(static_cast<int>(argv.size()), argv.data());
  result.out = ::testing::internal::GetCapturedStdout();
  result.err = ::testing::internal::GetCapturedStderr();
  return result;
}

}  // namespace relslam::test
