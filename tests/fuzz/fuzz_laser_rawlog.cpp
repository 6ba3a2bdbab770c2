// libFuzzer target: the 2-D laser log reader `relslam run --rawlog` uses for a laser scenario
// (read_laser_rawlog: CObservation2DRangeScan records with odometry, over the input written to
// a file) and the same bytes read from memory (read_rawlog_bytes). Bad input must end in
// InputError, nothing else. An accepted log gives what rawlog.hpp promises of a scan: numbered
// by position, at least 2 rays, one validity flag (0 or 1) per range, an aperture in (0, 2 pi]
// spread evenly and centred, maxRange in (0, kMaxSensorRange_m], every valid range finite and in
// [0, (1 + kRangeTolerance) maxRange], invalid ones 0, a finite scanner pose within
// kMaxSensorOffset_m and finite odometry; and both readings give the same scans.

#include "fuzz_support.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/rawlog.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <optional>
#include <vector>

namespace {

using relslam::fuzz::require;
using relslam::fuzz::require_finite;
namespace eval = relslam::eval;

void check_pose(const relslam::PlanarPose& p, const char* what) {
  require_finite(p.translation, what);
  require_finite(p.heading, what);
}

void check_scan(const eval::RawlogScan& s) {
  const relslam::LaserScan& scan = s.scan;
  require(scan.ranges.size() >= 2, "a scan of fewer than 2 rays");
  require(scan.valid.size() == scan.ranges.size(), "not one validity flag per range");
  require(scan.max_range > 0 && scan.max_range <= eval::kMaxSensorRange_m, "maxRange out of bounds");
  require(scan.bearing_step_rad > 0, "bearing step not positive");
  const double aperture = scan.bearing_step_rad * static_cast<double>(scan.size() - 1);
  require(aperture <= 2 * std::numbers::pi * (1 + 1e-12), "aperture above 2 pi");
  require(std::abs(scan.start_bearing_rad + 0.5 * aperture) <= 1e-9, "the rays are not centred");
  require_finite(scan.stamp_s, "stamp_s");
  check_pose(scan.robot_T_sensor, "robot_T_sensor");
  require(scan.robot_T_sensor.translation.cwiseAbs().maxCoeff() <= eval::kMaxSensorOffset_m, "sensor offset");
  const double limit = (1 + eval::kRangeTolerance) * scan.max_range;
  for (std::size_t i = 0; i < scan.size(); ++i) {
    require(scan.valid[i] == 0 || scan.valid[i] == 1, "a validity flag other than 0 or 1");
    const double r = scan.ranges[i];
    if (scan.valid[i])
      require(std::isfinite(r) && r >= 0 && r <= limit * (1 + 1e-6), "a valid range out of bounds");
    else
      require(r == 0, "an invalid ray with a range");
  }
  if (s.odometry) check_pose(*s.odometry, "odometry");
}

bool same(const eval::RawlogScan& a, const eval::RawlogScan& b) {
  const auto pose_eq = [](const relslam::PlanarPose& p, const relslam::PlanarPose& q) {
    return p.translation == q.translation && p.heading == q.heading;
  };
  return a.index == b.index && a.scan.ranges == b.scan.ranges && a.scan.valid == b.scan.valid &&
         a.scan.stamp_s == b.scan.stamp_s && a.scan.bearing_step_rad == b.scan.bearing_step_rad &&
         a.scan.max_range == b.scan.max_range && pose_eq(a.scan.robot_T_sensor, b.scan.robot_T_sensor) &&
         a.odometry.has_value() == b.odometry.has_value() && (!a.odometry || pose_eq(*a.odometry, *b.odometry));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static relslam::fuzz::ScratchFile file(".rawlog");
  const std::string_view bytes = relslam::fuzz::as_text(data, size);
  std::optional<eval::Rawlog> from_file;
  try {
    from_file = eval::read_laser_rawlog(file.write(bytes));
  } catch (const eval::InputError&) {
  }
  if (!from_file) return 0;
  require(!from_file->scans.empty(), "accepted a laser log without scans");
  for (std::size_t k = 0; k < from_file->scans.size(); ++k) {
    require(from_file->scans[k].index == static_cast<int>(k), "scan.index is not the scan's position");
    check_scan(from_file->scans[k]);
  }
  if (bytes.size() >= 2 && bytes[0] == '\x1f' && bytes[1] == '\x8b') return 0;  // gzip: a file only
  try {
    const eval::Rawlog memory = eval::read_rawlog_bytes(bytes, "fuzz.rawlog");
    require(memory.scans.size() == from_file->scans.size(), "file and memory give different scan counts");
    for (std::size_t k = 0; k < memory.scans.size(); ++k)
      require(same(memory.scans[k], from_file->scans[k]), "file and memory give different scans");
  } catch (const eval::InputError&) {
    require(false, "the bytes in memory are refused, the same file accepted");
  }
  return 0;
}
