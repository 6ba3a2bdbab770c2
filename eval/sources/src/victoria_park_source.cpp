#include "relslam/eval/sources/victoria_park_source.hpp"

#include <algorithm>
#include <numbers>

namespace relslam::eval {

std::optional<Eigen::Vector2d> gps_at(const std::vector<GpsFix>& gps, double t, double max_gap) {
  auto after = std::lower_bound(gps.begin(), gps.end(), t, [](const GpsFix& f, double time) { return f.time < time; });
  if (after == gps.end() || after == gps.begin()) return std::nullopt;
  const GpsFix& before = *(after - 1);
  if (t - before.time > max_gap || after->time - t > max_gap) return std::nullopt;
  const double w = (t - before.time) / (after->time - before.time);
  return (1 - w) * before.position + w * after->position;
}

VictoriaParkStream::VictoriaParkStream(const VictoriaParkLog& log, const Scenario& scenario)
    : filter_(scenario.victoria_park.filter), dead_reckoning_(log.inputs) {
  // The laser's range and field of view, for the EKF's gating.
  sensor_.min_range = filter_.min_range;
  sensor_.max_range = std::min(filter_.max_range, 81.91);  // 13-bit centimetre ranges
  sensor_.field_of_view_yaw_rad = std::numbers::pi;        // 0..180 degrees
  sensor_.std_range = scenario.ekf2d.std_range;
  sensor_.std_yaw_rad = scenario.ekf2d.std_yaw_rad;
}

std::optional<Pose2> VictoriaParkStream::motion(const std::vector<LaserScan>& scans, std::size_t i) const {
  if (i == 0) return std::nullopt;
  return dead_reckoning_.motion(scans[i - 1].time, scans[i].time);
}

ObservationFrame VictoriaParkStream::frame(const std::vector<LaserScan>& scans, std::size_t i) const {
  ObservationFrame frame;
  frame.iteration = static_cast<int>(i);
  for (const TreeDetection& tree : scans[i].trees)
    if (kept(filter_, tree)) {
      const Eigen::Vector2d p = laser_point(tree);
      frame.points.push_back(robot_from_mrpt({p.x(), p.y(), 0.0}));
    }
  if (const auto m = motion(scans, i)) frame.odometry = robot_pose_from_planar(*m);
  return frame;
}

VictoriaParkSource::VictoriaParkSource(const VictoriaParkLog& log, const Scenario& scenario,
                                       const std::filesystem::path& out)
    : log_(log),
      window_(scenario.victoria_park.window),
      scans_(scans_in(log, parse_scan_window(window_, "victoria_park.window"), "victoria_park.window")),
      stream_(log, scenario),
      out_(out) {
  truth_.known = false;
}

void VictoriaParkSource::stream(const Consumer& consume) {
  CsvWriter table(out_ / "scans.csv", {"iteration", "scan", "time", "trees", "kept", "odometry_x", "odometry_y",
                                       "odometry_heading", "gps_x", "gps_y"});
  TumWriter gps_tum(out_ / "gps.tum");
  for (std::size_t i = 0; i < scans_.size(); ++i) {
    const int k = static_cast<int>(i);
    const ObservationFrame frame = stream_.frame(scans_, i);
    const std::optional<Pose2> motion = stream_.motion(scans_, i);
    TruthFrame t;
    t.iteration = k;
    t.pose_known = false;
    t.landmark_ids.assign(frame.points.size(), -1);
    consume(frame, t);

    gps_.push_back(gps_at(log_.gps, scans_[i].time));
    const std::optional<Eigen::Vector2d>& fix = gps_.back();
    gps_scans_ += fix.has_value();
    scans_below_three_ += frame.points.size() < 3;
    if (fix) gps_tum.write(k, {Eigen::Matrix3d::Identity(), {fix->x(), fix->y(), 0.0}});
    table.row(k, scans_[i].index, scans_[i].time, scans_[i].trees.size(), frame.points.size(),
              motion ? std::optional(motion->x) : std::nullopt, motion ? std::optional(motion->y) : std::nullopt,
              motion ? std::optional(motion->heading) : std::nullopt, fix ? std::optional(fix->x()) : std::nullopt,
              fix ? std::optional(fix->y()) : std::nullopt);
  }
  table.close();
  gps_tum.close();
}

nlohmann::json VictoriaParkSource::describe() const {
  return {{"victoria_park",
           {{"window", window_},
            {"first_scan", scans_.empty() ? 0 : scans_.front().index},
            {"last_scan", scans_.empty() ? 0 : scans_.back().index},
            {"first_time", scans_.empty() ? 0.0 : scans_.front().time},
            {"last_time", scans_.empty() ? 0.0 : scans_.back().time},
            {"scans", scans()},
            {"scans_below_three_trees", scans_below_three_},
            {"scans_with_gps", gps_scans_}}}};
}

}  // namespace relslam::eval
