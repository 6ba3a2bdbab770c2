// Golden files: a tiny seeded run must reproduce the CSV and TUM files committed in
// tests/data/golden_sim/. Numbers are compared with a relative tolerance of 1e-12, far below
// any behaviour change but above last-bit differences between CPUs' libm (sin/cos in the
// path geometry). To accept an intended change: RELSLAM_UPDATE_GOLDEN=1 ctest -R Golden.
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace relslam {
namespace {

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  for (std::string f; std::getline(in, f, separator);) fields.push_back(f);
  return fields;
}

// Equal text, or both numbers within the tolerance.
bool same_field(const std::string& a, const std::string& b) {
  if (a == b) return true;
  char* end_a = nullptr;
  char* end_b = nullptr;
  const double x = std::strtod(a.c_str(), &end_a), y = std::strtod(b.c_str(), &end_b);
  if (*end_a != '\0' || *end_b != '\0' || a.empty() || b.empty()) return false;
  return std::abs(x - y) <= 1e-12 * std::max({1.0, std::abs(x), std::abs(y)});
}

void expect_same_table(const std::filesystem::path& expected, const std::filesystem::path& actual, char separator) {
  const auto want = test::read_lines(expected), got = test::read_lines(actual);
  ASSERT_EQ(want.size(), got.size()) << actual.filename();
  for (std::size_t i = 0; i < want.size(); ++i) {
    const auto a = split(want[i], separator), b = split(got[i], separator);
    ASSERT_EQ(a.size(), b.size()) << actual.filename() << " line " << i + 1;
    for (std::size_t j = 0; j < a.size(); ++j)
      ASSERT_TRUE(same_field(a[j], b[j]))
          << actual.filename() << " line " << i + 1 << " field " << j + 1 << ": want " << a[j] << ", got " << b[j];
  }
}

TEST(GoldenSimulation, TinySeededRunMatchesTheCommittedFiles) {
  test::ScratchDir dir;
  const auto golden = test::source_path("tests/data/golden_sim");
  const auto r =
      test::run_relslam({"simulate", (golden / "scenario.json").string(), "--out", (dir / "run").string(), "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::pair<std::string, char>> files = {{"ground_truth_path.tum", ' '},
                                                           {"ground_truth_landmarks.csv", ','},
                                                           {"ground_truth_dynamic.csv", ','},
                                                           {"sim_iterations.csv", ','},
                                                           {"observations.csv", ','}};
  if (std::getenv("RELSLAM_UPDATE_GOLDEN")) {
    for (const auto& [file, separator] : files)
      std::filesystem::copy_file(dir / "run" / file, golden / file, std::filesystem::copy_options::overwrite_existing);
    GTEST_SKIP() << "golden files rewritten in " << golden;
  }
  for (const auto& [file, separator] : files) expect_same_table(golden / file, dir / "run" / file, separator);
}

// Relative Point golden runs: short versions of shipped point scenarios must write
// the very CSV and TUM text committed in tests/data/golden_point/<case>/, byte for byte, except
// the measured times. Speed work must not change a single result: every index variant, storage
// layout and reuse keeps the summation order (README, "Same results").
// To accept an intended change: RELSLAM_UPDATE_GOLDEN=1 ctest -R GoldenRelativePoint.

// A CSV line without the fields of the dropped columns; empty fields (missing values) stay,
// trailing ones included.
std::string without_columns(const std::string& line, const std::vector<bool>& drop) {
  std::string kept;
  bool first = true;
  std::size_t column = 0, begin = 0;
  for (;;) {
    const std::size_t end = std::min(line.find(',', begin), line.size());
    if (column >= drop.size() || !drop[column]) {
      if (!first) kept += ',';
      kept.append(line, begin, end - begin);
      first = false;
    }
    if (end == line.size()) return kept;
    begin = end + 1;
    ++column;
  }
}

// The file as text, CSV files without their timing columns (`*_ms`, `peak_rss_mb`): the only
// values that differ between two runs of one scenario (README, "Run folders").
std::string deterministic_text(const std::filesystem::path& file) {
  const auto lines = test::read_lines(file);
  if (file.extension() != ".csv" || lines.empty()) {
    std::string text;
    for (const auto& line : lines) text += line + '\n';
    return text;
  }
  const auto header = split(lines.front(), ',');
  std::vector<bool> drop(header.size());
  for (std::size_t j = 0; j < header.size(); ++j)
    drop[j] = header[j] == "peak_rss_mb" || (header[j].size() > 3 && header[j].ends_with("_ms"));
  std::string text;
  for (const auto& line : lines) text += without_columns(line, drop) + '\n';
  return text;
}

struct GoldenCase {
  std::string name;  // folder under tests/data/<folder>
  std::string scenario;
  std::vector<std::string> overrides;
};

// summary.csv and every CSV and TUM file of the run's algorithm folders, relative to the run.
std::vector<std::string> result_files(const std::filesystem::path& run) {
  std::vector<std::string> files = {"summary.csv"};
  for (const auto& entry : std::filesystem::recursive_directory_iterator(run)) {
    const auto relative = entry.path().lexically_relative(run);
    const auto ext = entry.path().extension();
    if (entry.is_regular_file() && relative.has_parent_path() && (ext == ".csv" || ext == ".tum"))
      files.push_back(relative.string());
  }
  std::sort(files.begin() + 1, files.end());
  return files;
}

// Runs the case and compares its result files with tests/data/<folder>/<case>/, byte for byte
// but for the measured times; RELSLAM_UPDATE_GOLDEN=1 rewrites them instead.
void expect_golden(const std::string& folder, const GoldenCase& c) {
  test::ScratchDir dir;
  const auto golden = test::source_path("tests/data/" + folder) / c.name;
  std::vector<std::string> args = {"run", test::source_path(c.scenario).string(), "--out", (dir / "run").string(), "-q",
                                   "--set", "output.observations_csv=false", "--set", "output.rawlog=false"};
  for (const auto& o : c.overrides) args.insert(args.end(), {"--set", o});
  const auto r = test::run_relslam(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> files = result_files(dir / "run");
  if (std::getenv("RELSLAM_UPDATE_GOLDEN")) {
    std::filesystem::remove_all(golden);
    for (const auto& file : files) {
      std::filesystem::create_directories((golden / file).parent_path());
      test::write_file(golden / file, deterministic_text(dir / "run" / file));
    }
    GTEST_SKIP() << "golden files rewritten in " << golden;
  }
  EXPECT_EQ(files, result_files(golden)) << c.name << ": the run writes other files than the committed ones";
  for (const auto& file : files) {
    if (!std::filesystem::exists(golden / file)) continue;
    const std::string want = test::read_file(golden / file), got = deterministic_text(dir / "run" / file);
    if (want == got) continue;
    const auto want_lines = split(want, '\n'), got_lines = split(got, '\n');
    std::size_t i = 0;
    while (i < want_lines.size() && i < got_lines.size() && want_lines[i] == got_lines[i]) ++i;
    ADD_FAILURE() << c.name << "/" << file << " differs first at line " << i + 1 << ":\n  want "
                  << (i < want_lines.size() ? want_lines[i] : "(end)") << "\n  got  "
                  << (i < got_lines.size() ? got_lines[i] : "(end)");
  }
}

void expect_point_golden(const GoldenCase& c) { expect_golden("golden_point", c); }

TEST(GoldenRelativePoint, FigureEightAtDensity100MatchesTheCommittedFiles) {
  expect_point_golden({"f8_density100", "scenarios/s-f8.json", {"sim.iterations=400"}});
}

TEST(GoldenRelativePoint, FigureEightAtDensity550MatchesTheCommittedFiles) {
  expect_point_golden({"f8_density550", "scenarios/s-f8.json", {"sim.iterations=250", "sim.density=550"}});
}

TEST(GoldenRelativePoint, OctreeAtDensity550MatchesTheCommittedFiles) {
  expect_point_golden({"dens_o_density550", "scenarios/s-dens-o.json", {"sim.iterations=200", "sim.density=550"}});
}

TEST(GoldenRelativePoint, SmallQuadsMatchesTheCommittedFiles) {
  expect_point_golden({"dens_qs_density100", "scenarios/s-dens-qs.json", {"sim.iterations=300"}});
}

TEST(GoldenRelativePoint, DynamicPointsMatchTheCommittedFiles) {
  expect_point_golden({"dyn3_density100", "scenarios/s-dyn3.json", {"sim.iterations=400"}});
}

// Relative Plane and EM golden runs: short versions of shipped planar scenarios (the plane
// sensor, the point sensor with EM in the loop, roll-backs) write the committed CSV and TUM text
// of every file of their algorithm folders, but for the measured times. A restructuring of the
// plane half must not change a single byte of them.
TEST(GoldenRelativePlane, MapEMotionRoomMatchesTheCommittedFiles) {
  expect_golden("golden_plane", {"room", "scenarios/p-room.json", {"planar.iterations=700"}});
}

TEST(GoldenRelativePlane, MapDOfficeMatchesTheCommittedFiles) {
  expect_golden("golden_plane", {"office", "scenarios/p-office.json", {"planar.iterations=700"}});
}

TEST(GoldenRelativePlane, SaveSystemRunMatchesTheCommittedFiles) {
  expect_golden("golden_plane", {"e19", "scenarios/p-e19-save-system.json", {"planar.iterations=700"}});
}

TEST(GoldenRelativePlane, EmInTheLoopMatchesTheCommittedFiles) {
  expect_golden("golden_plane", {"em_room", "scenarios/p-em-room.json", {"planar.iterations=300"}});
}

}  // namespace
}  // namespace relslam
