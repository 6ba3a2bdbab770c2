#pragma once
// Settings of MRPT's ICP-SLAM (CMetricMapBuilderICP on a planar point map), the scan-matching
// baseline of the planar half on laser scans. The defaults are those of MRPT's shipped
// icp-slam_demo_classic.ini (the one MRPT maps its SENA log with) [C: MRPT's demo]; the keys
// are its .ini names in snake case. describe() gives each field's key, help and checks
// (relslam/core/option_fields.hpp).

#include "relslam/core/option_fields.hpp"

#include <numbers>
#include <string>
#include <string_view>

namespace relslam::eval {

// MRPT's ICP_algorithm: classic (point to point, thresholds shrunk by alfa) or
// Levenberg–Marquardt.
enum class IcpMethod { Classic, LevenbergMarquardt };
inline constexpr IcpMethod kIcpMethods[] = {IcpMethod::Classic, IcpMethod::LevenbergMarquardt};
inline std::string_view to_string(IcpMethod m) { return m == IcpMethod::Classic ? "classic" : "levenberg_marquardt"; }

// The largest pairing distance a scenario may give ICP [C: beyond any indoor scan's pairs].
inline constexpr double kMaxIcpDistance_m = 100.0;

struct IcpSlamOptions {
  // [ICP]
  int max_iterations = 80;
  double min_abs_step_trans = 1e-6;                             // m
  double min_abs_step_rot_rad = 1e-6;                           // rad
  double threshold_dist = 0.3;                                  // m, initial pairing distance
  double threshold_ang_rad = 5.0 * std::numbers::pi / 180.0;    // grows the distance for far points
  double alfa = 0.8;                                            // threshold shrink after convergence
  double smallest_threshold_dist = 0.05;                        // m
  bool only_unique_robust = true;
  IcpMethod method = IcpMethod::Classic;
  int corresponding_points_decimation = 5;
  // [MappingApplication]
  double localization_lin_distance = 0.2;                             // m moved before ICP corrects
  double localization_ang_distance_rad = 5.0 * std::numbers::pi / 180.0;
  double insertion_lin_distance = 1.2;                                // m moved before a scan joins the map
  double insertion_ang_distance_rad = 45.0 * std::numbers::pi / 180.0;
  double min_icp_goodness_to_accept = 0.40;
  // [MappingApplication_pointsMap_00_insertOpts]
  double min_dist_between_laser_points = 0.05;  // m
  // The frames' odometry as the action before each scan (icp-slam reads the log's); without it
  // every scan is matched from the last estimate (a constant-position model) [C: the log's use].
  bool use_odometry = true;
};

// The scenario keys of IcpSlamOptions (icp_slam.*).
void describe(OptionsOf<IcpSlamOptions> auto& o, auto& f) {
  f.field("max_iterations", o.max_iterations, "ICP iterations at most per scan", at_least(1), at_most(100000));
  f.field("min_abs_step_trans", o.min_abs_step_trans, "ICP stops below this translation step, m", above(0.0));
  f.field("min_abs_step_rot", o.min_abs_step_rot_rad, "ICP stops below this rotation step, rad", above(0.0));
  // Pairing distances up to the longest laser range (MRPT shrinks the threshold by alfa until the
  // smallest: from 1e300 that took longer than any run) [C].
  f.field("threshold_dist", o.threshold_dist, "initial pairing distance, m", above(0.0), at_most(kMaxIcpDistance_m));
  f.degrees("threshold_ang_deg", o.threshold_ang_rad, "pairing distance growth with a point's range, degrees",
            at_least(0.0), at_most(90.0));
  // MRPT's ICP asserts alfa < 1 (at 1 it failed the run with MRPT's stack trace as its status) [C].
  f.field("alfa", o.alfa, "thresholds times this after convergence", above(0.0), at_most(0.99));
  f.field("smallest_threshold_dist", o.smallest_threshold_dist, "smallest pairing distance, m", above(0.0),
          at_most(o.threshold_dist, "threshold_dist"));
  f.field("only_unique_robust", o.only_unique_robust, "unique pairs in both directions");
  f.choice("method", o.method, "ICP variant: classic or levenberg_marquardt", kIcpMethods);
  f.field("corresponding_points_decimation", o.corresponding_points_decimation,
          "match every n-th point of the scan", at_least(1), at_most(10000));
  f.field("localization_lin_distance", o.localization_lin_distance, "distance moved before ICP corrects, m",
          at_least(0.0));
  f.degrees("localization_ang_distance_deg", o.localization_ang_distance_rad, "turn before ICP corrects, degrees",
            at_least(0.0), at_most(360.0));
  f.field("insertion_lin_distance", o.insertion_lin_distance, "distance moved before a scan joins the map, m",
          at_least(0.0));
  f.degrees("insertion_ang_distance_deg", o.insertion_ang_distance_rad,
            "turn before a scan joins the map, degrees", at_least(0.0), at_most(360.0));
  f.field("min_icp_goodness_to_accept", o.min_icp_goodness_to_accept, "least ICP goodness to accept a match",
          at_least(0.0), at_most(1.0));
  f.field("min_dist_between_laser_points", o.min_dist_between_laser_points,
          "point map: closest two inserted points, m", at_least(0.0));
  f.field("use_odometry", o.use_odometry, "feed the frames' odometry (where they carry it) as the action");
}

}  // namespace relslam::eval
