#include "relslam/eval/cli/commands/rawlog_info.hpp"

#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/io/point_cloud_rawlog.hpp"
#include "relslam/eval/io/rawlog.hpp"
#include "relslam/eval/sources/rawlog_source.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdio>
#include <numbers>

namespace relslam::eval {

void add_rawlog(CLI::App& app, RawlogArgs& args) {
  CLI::App* cmd = app.add_subcommand("rawlog", "Read an MRPT rawlog as relslam sees it");
  cmd->description(
      "Read an MRPT rawlog (either format, plain or gzip) the way relslam's algorithms will see it and\n"
      "summarise it: format, frames, points per frame, landmark ids, odometry (for a log of 2-D laser\n"
      "scans: scans, rays, aperture, maximum range, odometry). --csv writes every\n"
      "detection in relslam's robot frame (+x left, +y up, +z forward), one row per point.\n"
      "A rawlog of point clouds (CObservation3DRangeScan, CObservationVelodyneScan,\n"
      "CObservationPointCloud) is summarised cloud by cloud: pixels, returns, intrinsics, extent;\n"
      "relslam extract finds their planes.");
  cmd->add_option("rawlog", args.file, "Rawlog file")->required();
  cmd->add_option("--csv", args.csv,
                  "Write frame,x,y,z,landmark_id rows to this CSV file (a laser log: one row per scan, its odometry)");
}

namespace {

// The sensor as the first observation describes it: its noise is what the EKFs take from the
// log, its pose on the robot what turns every measurement into robot coordinates.
void print_sensor(const Rawlog& log) {
  const RangeBearingSensor& s = log.sensor;
  constexpr double kDeg = 180.0 / std::numbers::pi;
  std::printf("  sensor noise: std range %g m, yaw %g deg, pitch %g deg%s\n", s.std_range, s.std_yaw_rad * kDeg,
              s.std_pitch_rad * kDeg, s.std_range > 0 ? "" : " (none given)");
  const Rigid3& pose = log.frames.front().robot_T_sensor;
  const Eigen::Vector3d& t = pose.translation;
  const double angle = Eigen::AngleAxisd(pose.rotation).angle() * kDeg;
  std::printf("  sensor on robot (MRPT axes): x %g y %g z %g m, rotated %g deg\n", t.x(), t.y(), t.z(), angle);
}

// A log's 2-D laser scans: rays, aperture, maximum range, the scanner on the robot, odometry.
void print_scans(const Rawlog& log) {
  constexpr double kDeg = 180.0 / std::numbers::pi;
  std::size_t rays = 0, valid = 0, min_rays = SIZE_MAX, max_rays = 0, odometry = 0;
  double path = 0, turn = 0;
  for (const RawlogScan& s : log.scans) {
    rays += s.scan.size();
    valid += static_cast<std::size_t>(std::count(s.scan.valid.begin(), s.scan.valid.end(), 1));
    min_rays = std::min(min_rays, s.scan.size());
    max_rays = std::max(max_rays, s.scan.size());
    if (!s.odometry) continue;
    ++odometry;
    path += s.odometry->translation.norm();
    turn += std::abs(s.odometry->heading);
  }
  const LaserScan& first = log.scans.front().scan;
  const double aperture = first.bearing_step_rad * static_cast<double>(first.size() - 1) * kDeg;
  std::printf("  2-D laser scans: %zu (rays per scan %zu..%zu, %.1f %% valid)\n", log.scans.size(), min_rays,
              max_rays, 100.0 * static_cast<double>(valid) / static_cast<double>(std::max<std::size_t>(rays, 1)));
  std::printf("  first scan: aperture %g deg, %g deg between rays, max range %g m\n", aperture,
              first.bearing_step_rad * kDeg, first.max_range);
  const PlanarPose& s = first.robot_T_sensor;
  std::printf("  scanner on robot: x %g y %g m (MRPT axes), yaw %g deg\n", s.translation.x(), s.translation.y(),
              s.heading * kDeg);
  std::printf("  odometry: %zu of %zu scans, %.2f m and %.1f deg in all\n", odometry, log.scans.size(), path,
              turn * kDeg);
  std::printf("  time: %.3f .. %.3f s\n", first.stamp_s, log.scans.back().scan.stamp_s);
}

// One row per scan: its time, rays with a return, and the odometry since the previous scan
// (planar axes: MRPT's x, y, yaw as x, z, heading; empty without).
void write_scan_rows(const Rawlog& log, const std::string& file) {
  CsvWriter csv(file, {"scan", "stamp_s", "rays", "valid", "odo_x", "odo_z", "odo_heading_deg"});
  for (const RawlogScan& s : log.scans) {
    const auto valid = static_cast<long long>(std::count(s.scan.valid.begin(), s.scan.valid.end(), 1));
    const std::optional<PlanarPose>& o = s.odometry;
    csv.row(s.index, s.scan.stamp_s, static_cast<long long>(s.scan.size()), valid,
            o ? csv_field(o->translation.x()) : CsvField{}, o ? csv_field(o->translation.y()) : CsvField{},
            o ? csv_field(o->heading * 180.0 / std::numbers::pi) : CsvField{});
  }
  csv.close();
  std::printf("wrote %s\n", file.c_str());
}

}  // namespace

int run_rawlog(const RawlogArgs& args) {
  if (starts_with_point_cloud(args.file)) return run_point_cloud_rawlog(args);
  const Rawlog log = read_rawlog(args.file);
  if (log.frames.empty()) {
    std::printf("%s: a 2-D laser log, %d records (%d other observations skipped)\n", args.file.c_str(), log.records,
                log.skipped_observations);
    print_scans(log);
    if (!args.csv.empty()) write_scan_rows(log, args.csv);
    return 0;
  }
  std::size_t points = 0, min_points = SIZE_MAX, max_points = 0, known = 0, odometry = 0;
  for (const RawlogFrame& f : log.frames) {
    points += f.measurements.size();
    min_points = std::min(min_points, f.measurements.size());
    max_points = std::max(max_points, f.measurements.size());
    known +=
        std::count_if(f.measurements.begin(), f.measurements.end(), [](const auto& m) { return m.landmark_id >= 0; });
    odometry += f.odometry.has_value();
  }
  const char* format = log.format == Rawlog::Format::ObservationsOnly ? "observations only"
                       : log.sensory_frame_first                      ? "actions/sensory frames, sensory frame first"
                                                                      : "actions/sensory frames, action first";
  std::printf("%s: %s\n", args.file.c_str(), format);
  std::printf("  %zu frames in %d records (%d other observations skipped)\n", log.frames.size(), log.records,
              log.skipped_observations);
  std::printf("  points per frame: mean %.1f, min %zu, max %zu\n", static_cast<double>(points) / log.frames.size(),
              min_points, max_points);
  std::printf("  landmark ids: %s\n", known == points ? "all known" : known == 0 ? "all unknown (-1)" : "mixed");
  std::printf("  odometry: %zu of %zu frames\n", odometry, log.frames.size());
  std::printf("  time: %.3f .. %.3f s\n", log.frames.front().timestamp_s, log.frames.back().timestamp_s);
  // What relslam run makes of it: a planar log runs relative_point + ekf2d (rawlog_defaults.hpp).
  const RawlogShape shape = shape_of(log);
  std::printf("  %s: %s\n", shape.planar ? "planar (2D)" : "3D", shape.why.c_str());
  print_sensor(log);

  if (!args.csv.empty()) {
    CsvWriter csv(args.csv, {"frame", "x", "y", "z", "landmark_id"});
    for (const RawlogFrame& f : log.frames) {
      const ObservationFrame frame = observation_frame(f);
      for (std::size_t i = 0; i < frame.points.size(); ++i)
        csv.row(f.index, frame.points[i].x(), frame.points[i].y(), frame.points[i].z(), f.measurements[i].landmark_id);
    }
    csv.close();
    std::printf("wrote %s\n", args.csv.c_str());
  }
  return 0;
}

}  // namespace relslam::eval
