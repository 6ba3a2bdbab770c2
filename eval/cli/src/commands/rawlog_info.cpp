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
      "summarise it: format, frames, points per frame, landmark ids, odometry. --csv writes every\n"
      "detection in relslam's robot frame (+x left, +y up, +z forward), one row per point.\n"
      "A rawlog of point clouds (CObservation3DRangeScan, CObservationVelodyneScan,\n"
      "CObservationPointCloud) is summarised cloud by cloud: pixels, returns, intrinsics, extent;\n"
      "relslam extract finds their planes.");
  cmd->add_option("rawlog", args.file, "Rawlog file")->required();
  cmd->add_option("--csv", args.csv, "Write frame,x,y,z,landmark_id rows to this CSV file");
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

}  // namespace

int run_rawlog(const RawlogArgs& args) {
  if (starts_with_point_cloud(args.file)) return run_point_cloud_rawlog(args);
  const Rawlog log = read_rawlog(args.file);
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
