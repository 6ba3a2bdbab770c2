#pragma once
// Settings of MRPT's planar EKF-SLAM (CRangeBearingKFSLAM2D), the Victoria Park reference
// (thesis 6.8). Run with the vehicle's odometry (algorithm ekf2d) and,
// for comparison with the odometry-free algorithms, without it (ekf2d_no_odometry).
// describe() gives each field's key, help and checks (relslam/core/option_fields.hpp).

#include "relslam/core/option_fields.hpp"
#include "relslam/eval/config/ekf_divergence_options.hpp"
#include "relslam/eval/config/ekf6d_options.hpp"

#include <numbers>
#include <vector>

namespace relslam::eval {

struct Ekf2dOptions {
  EkfMethod method = EkfMethod::Davison;
  // Victoria Park's trees carry no ids: the filter associates them itself [C].
  EkfAssociation association = EkfAssociation::Jcbb;
  // Without odometry the filter loses its pose on long runs; its covariance then makes every
  // nearby landmark compatible with every tree and JCBB's search grows exponentially (measured:
  // one scan of the whole log ran for over 25 minutes). Nearest neighbour costs O(trees x map)
  // per scan, so the time budget can stop it [C].
  EkfAssociation association_no_odometry = EkfAssociation::Nn;
  // Sensor model. A trunk's centre comes from a laser arc, so its range is uncertain by a good
  // part of the trunk's diameter (up to 1.5 m) [C].
  double std_range = 0.5;                               // m
  double std_yaw_rad = 1.0 * std::numbers::pi / 180.0;  // read and written in degrees
  // Without odometry: constant-position noise per scan (x, y in m, heading in rad); the vehicle
  // moves up to 1.4 m and turns a few degrees per scan [C].
  std::vector<double> stds_q_no_odometry = {1.0, 1.0, 5.0 * std::numbers::pi / 180.0};
  // With odometry: the standard deviation of each scan's dead-reckoned motion, a floor plus a
  // share of the motion itself [C].
  double odometry_std_xy = 0.05;       // m
  double odometry_std_xy_ratio = 0.1;  // of the distance moved
  double odometry_std_heading_rad = 0.5 * std::numbers::pi / 180.0;
  double odometry_std_heading_ratio = 0.1;  // of the heading change
  // Algorithm ekf2d outside Victoria Park (a rawlog, a simulation): feed the frames' odometry.
  // Off by default, the thesis's comparison without odometry; Victoria Park's ekf2d is the
  // reference with the vehicle's odometry and always has it (6.8) [T].
  bool use_odometry = false;
  double chi2_threshold = 0.99;  // individual compatibility test of JCBB / NN
  double time_budget_ms = 1000.0;
  int budget_iterations = 20;
  // A run whose innovations outgrow the filter's own covariance ends lost, not ok [C].
  EkfDivergenceOptions divergence;
};

// The scenario keys of Ekf2dOptions (ekf2d.*): help and checks per field.
void describe(OptionsOf<Ekf2dOptions> auto& o, auto& f) {
  f.choice("method", o.method, "planar EKF update: davison or full", kEkfMethods);
  f.choice("association", o.association, "jcbb or nn (Victoria Park has no ids), or known", kEkfAssociations);
  f.choice("association_no_odometry", o.association_no_odometry,
           "ekf2d_no_odometry's association: nn (bounded time per scan), jcbb or known", kEkfAssociations);
  f.field("std_range", o.std_range, "planar EKF: range std. deviation, m", at_least(kMinSensorStd));
  f.degrees("std_yaw_deg", o.std_yaw_rad, "planar EKF: bearing std. deviation", at_least(kMinSensorStd));
  f.field("stds_q_no_odometry", o.stds_q_no_odometry,
          "planar EKF without odometry: motion noise per scan x, y (m), heading (rad)", length(3, "x, y, heading"),
          above(0.0));
  f.field("odometry_std_xy", o.odometry_std_xy, "odometry std. deviation per scan, m (floor)", above(0.0));
  f.field("odometry_std_xy_ratio", o.odometry_std_xy_ratio, "...plus this share of the distance moved", at_least(0.0));
  f.degrees("odometry_std_heading_deg", o.odometry_std_heading_rad, "odometry heading std. deviation per scan (floor)",
            above(0.0));
  f.field("odometry_std_heading_ratio", o.odometry_std_heading_ratio, "...plus this share of the heading change",
          at_least(0.0));
  f.field("use_odometry", o.use_odometry,
          "ekf2d on a rawlog or simulation: feed the frames' odometry (Victoria Park's ekf2d always does)");
  f.field("chi2_threshold", o.chi2_threshold, "planar EKF: data association compatibility", above(0.0), at_most(1.0));
  f.field("time_budget_ms", o.time_budget_ms, "stop the planar EKF past this time per scan", above(0.0));
  f.field("budget_iterations", o.budget_iterations, "...once its mean over this many scans exceeds it", at_least(1));
  f.nested("divergence", o.divergence);
}

}  // namespace relslam::eval
