#include "relslam/eval/io/victoria_park.hpp"

#include "numeric_rows.hpp"
#include "relslam/core/option_issue.hpp"
#include "relslam/eval/config/input_error.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <numbers>

namespace relslam::eval {
namespace {

// The files give times to the millisecond: scans and detections pair on that key.
long long millis(double seconds) { return std::llround(seconds * 1000.0); }

// A row's time (column 0). The log spans about 1.5 hours; a time beyond a billion seconds is
// corrupt, and past 9e15 s its millisecond key would not fit the integer it is paired on.
double time_of(const NumericRow& row, const std::string& file) {
  if (std::abs(row.values[0]) > 1e9) throw InputError(file, row.line, "time", "must be within +-1e9 s");
  return row.values[0];
}

// Rows whose first column is a time that never goes back. Dead reckoning and the GPS lookup
// both search by time, so an unordered file would be misread silently (a reversed gps.dat
// matched no scan at all); name the first row out of order instead.
std::vector<NumericRow> timed_rows(std::string_view text, const std::string& file, std::size_t min_columns,
                                   const char* columns_hint) {
  std::vector<NumericRow> rows = parse_numeric_rows(text, file, min_columns, columns_hint);
  for (std::size_t i = 1; i < rows.size(); ++i)
    if (rows[i].values[0] < rows[i - 1].values[0])
      throw InputError(file, rows[i].line, "time",
                       "times must not decrease (line " + std::to_string(rows[i - 1].line) + " is later)");
  return rows;
}

// Column `column` of `row` within +-limit (a corrupt value would overflow the estimates).
double within(const NumericRow& row, std::size_t column, double limit, const std::string& file, const char* field) {
  const double value = row.values[column];
  if (std::abs(value) > limit)
    throw InputError(file, row.line, field,
                     "must be within +-" + format_number(limit) + ", got " + format_number(value));
  return value;
}

}  // namespace

Eigen::Vector2d laser_point(const TreeDetection& tree) {
  const double b = tree.bearing - std::numbers::pi / 2;
  return {tree.range * std::cos(b), tree.range * std::sin(b)};
}

VictoriaParkLog read_victoria_park(const std::filesystem::path& dir) {
  VictoriaParkText text;
  for (const auto& [name, content] : {std::pair{"Sensors_manager.txt", &text.sensors_manager},
                                      {"measurements.dat", &text.measurements},
                                      {"inputs.dat", &text.inputs},
                                      {"gps.dat", &text.gps}}) {
    const std::filesystem::path file = dir / name;
    if (!std::filesystem::exists(file)) throw InputError(file.string(), 0, "", "file not found");
    if (std::filesystem::is_directory(file)) throw InputError(file.string(), 0, "", "is a directory, not a data file");
    std::ifstream in(file, std::ios::binary);
    content->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return parse_victoria_park(text, dir);
}

VictoriaParkLog parse_victoria_park(const VictoriaParkText& text, const std::filesystem::path& dir) {
  VictoriaParkLog log;
  // Listed scans, in file order.
  const std::string sensors = (dir / "Sensors_manager.txt").string();
  std::map<long long, int> scan_at;  // time key -> position in log.scans
  for (const NumericRow& row : parse_numeric_rows(text.sensors_manager, sensors, 3, "time sensor index")) {
    if (row.values[1] != 3) continue;
    const double time = time_of(row, sensors);
    if (!log.scans.empty() && time <= log.scans.back().time)
      throw InputError(sensors, row.line, "", "laser times must increase");
    scan_at[millis(time)] = static_cast<int>(log.scans.size());
    log.scans.push_back({static_cast<int>(log.scans.size()) + 1, time, {}});
  }
  // Scan numbers count the laser lines; without one no detection can be placed in time.
  if (log.scans.empty()) throw InputError(sensors, 0, "", "no laser line (sensor 3): no scan to number");
  log.listed_scans = static_cast<int>(log.scans.size());
  const double last_listed = log.scans.back().time;

  const std::string measurements = (dir / "measurements.dat").string();
  for (const NumericRow& row : parse_numeric_rows(text.measurements, measurements, 4, "time range bearing diameter")) {
    const double time = time_of(row, measurements);
    const TreeDetection tree{within(row, 1, kMaxVictoriaParkRange_m, measurements, "range"), row.values[2],
                             within(row, 3, kMaxVictoriaParkRange_m, measurements, "diameter")};
    if (tree.range <= 0 || tree.bearing < 0 || tree.bearing > std::numbers::pi || tree.diameter < 0)
      throw InputError(measurements, row.line, "", "range must be > 0, bearing in [0, pi], diameter >= 0");
    auto it = scan_at.find(millis(time));
    if (it == scan_at.end()) {
      if (time <= last_listed)
        throw InputError(measurements, row.line, "", "no laser scan at time " + std::to_string(time));
      // Scans recorded after the sensor list ends (19 in the distributed files).
      if (time <= log.scans.back().time)
        throw InputError(measurements, row.line, "", "times must increase after the listed scans");
      it = scan_at.emplace(millis(time), static_cast<int>(log.scans.size())).first;
      log.scans.push_back({static_cast<int>(log.scans.size()) + 1, time, {}});
    }
    log.scans[it->second].trees.push_back(tree);
    ++log.detections;
  }

  const std::string inputs = (dir / "inputs.dat").string();
  for (const NumericRow& row : timed_rows(text.inputs, inputs, 3, "time speed steering"))
    log.inputs.push_back({row.values[0], within(row, 1, kMaxVictoriaParkSpeed_mps, inputs, "speed"),
                          within(row, 2, kMaxVictoriaParkSteering_rad, inputs, "steering")});
  const std::string gps = (dir / "gps.dat").string();
  for (const NumericRow& row : timed_rows(text.gps, gps, 3, "time x y"))
    log.gps.push_back({row.values[0],
                       {within(row, 1, kMaxVictoriaParkCoordinate_m, gps, "x"),
                        within(row, 2, kMaxVictoriaParkCoordinate_m, gps, "y")}});
  return log;
}

std::filesystem::path victoria_park_dir(const std::string& flag) {
  if (!flag.empty()) return flag;
  if (const char* env = std::getenv("RELSLAM_VICTORIA_PARK"); env && *env) return env;
  return "../shared/datasets/victoria_park";
}

std::vector<LaserScan> scans_in(const VictoriaParkLog& log, const ScanWindow& window, const std::string& field) {
  const int count = static_cast<int>(log.scans.size());
  const int last = std::min(window.last, count);
  if (window.first > count || (window.last != ScanWindow{}.last && window.last > count))
    throw InputError(
        "", 0, field,
        "the log has " + std::to_string(count) + " scans; the window ends at " + std::to_string(window.last));
  return {log.scans.begin() + (window.first - 1), log.scans.begin() + last};
}

}  // namespace relslam::eval
