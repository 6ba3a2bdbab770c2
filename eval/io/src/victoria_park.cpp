#include "relslam/eval/io/victoria_park.hpp"

#include "numeric_rows.hpp"
#include "relslam/eval/config/input_error.hpp"

#include <cmath>
#include <cstdlib>
#include <map>
#include <numbers>

namespace relslam::eval {
namespace {

// The files give times to the millisecond: scans and detections pair on that key.
long long millis(double seconds) { return std::llround(seconds * 1000.0); }

}  // namespace

Eigen::Vector2d laser_point(const TreeDetection& tree) {
  const double b = tree.bearing - std::numbers::pi / 2;
  return {tree.range * std::cos(b), tree.range * std::sin(b)};
}

VictoriaParkLog read_victoria_park(const std::filesystem::path& dir) {
  VictoriaParkLog log;
  // Listed scans, in file order.
  std::map<long long, int> scan_at;  // time key -> position in log.scans
  for (const NumericRow& row : read_numeric_rows(dir / "Sensors_manager.txt", 3, "time sensor index")) {
    if (row.values[1] != 3) continue;
    const double time = row.values[0];
    if (!log.scans.empty() && time <= log.scans.back().time)
      throw InputError((dir / "Sensors_manager.txt").string(), row.line, "", "laser times must increase");
    scan_at[millis(time)] = static_cast<int>(log.scans.size());
    log.scans.push_back({static_cast<int>(log.scans.size()) + 1, time, {}});
  }
  log.listed_scans = static_cast<int>(log.scans.size());
  const double last_listed = log.scans.empty() ? -1.0 : log.scans.back().time;

  const std::filesystem::path measurements = dir / "measurements.dat";
  for (const NumericRow& row : read_numeric_rows(measurements, 4, "time range bearing diameter")) {
    const double time = row.values[0];
    const TreeDetection tree{row.values[1], row.values[2], row.values[3]};
    if (tree.range <= 0 || tree.bearing < 0 || tree.bearing > std::numbers::pi || tree.diameter < 0)
      throw InputError(measurements.string(), row.line, "", "range must be > 0, bearing in [0, pi], diameter >= 0");
    auto it = scan_at.find(millis(time));
    if (it == scan_at.end()) {
      if (time <= last_listed)
        throw InputError(measurements.string(), row.line, "", "no laser scan at time " + std::to_string(time));
      // Scans recorded after the sensor list ends (19 in the distributed files).
      if (time <= log.scans.back().time)
        throw InputError(measurements.string(), row.line, "", "times must increase after the listed scans");
      it = scan_at.emplace(millis(time), static_cast<int>(log.scans.size())).first;
      log.scans.push_back({static_cast<int>(log.scans.size()) + 1, time, {}});
    }
    log.scans[it->second].trees.push_back(tree);
    ++log.detections;
  }

  for (const NumericRow& row : read_numeric_rows(dir / "inputs.dat", 3, "time speed steering"))
    log.inputs.push_back({row.values[0], row.values[1], row.values[2]});
  for (const NumericRow& row : read_numeric_rows(dir / "gps.dat", 3, "time x y"))
    log.gps.push_back({row.values[0], {row.values[1], row.values[2]}});
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
