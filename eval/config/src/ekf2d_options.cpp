#include "relslam/eval/config/ekf2d_options.hpp"

namespace relslam::eval {

std::vector<OptionIssue> check(const Ekf2dOptions& o) {
  std::vector<OptionIssue> issues;
  require_above(issues, "std_range", o.std_range, 0.0);
  require_above(issues, "std_yaw_deg", o.std_yaw_rad, 0.0);
  if (o.stds_q_no_odometry.size() != 3)
    issues.push_back({"stds_q_no_odometry", "needs 3 values (x, y, heading), got " + std::to_string(o.stds_q_no_odometry.size())});
  for (double s : o.stds_q_no_odometry) require_above(issues, "stds_q_no_odometry", s, 0.0);
  require_above(issues, "odometry_std_xy", o.odometry_std_xy, 0.0);
  require_at_least(issues, "odometry_std_xy_ratio", o.odometry_std_xy_ratio, 0.0);
  require_above(issues, "odometry_std_heading_deg", o.odometry_std_heading_rad, 0.0);
  require_at_least(issues, "odometry_std_heading_ratio", o.odometry_std_heading_ratio, 0.0);
  check_filter_limits(issues, o.chi2_threshold, o.time_budget_ms, o.budget_iterations);
  return issues;
}

}  // namespace relslam::eval
