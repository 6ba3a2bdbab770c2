#pragma once
// Settings of MRPT's planar EKF-SLAM (CRangeBearingKFSLAM2D), the Victoria Park reference
// (thesis 6.8; spec mrpt §1.5, §5). Run with the vehicle's odometry (algorithm ekf2d) and,
// for comparison with the odometry-free algorithms, without it (ekf2d_no_odometry).

#include "relslam/core/option_issue.hpp"
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
  double std_range = 0.5;                                // m
  double std_yaw_rad = 1.0 * std::numbers::pi / 180.0;   // read and written in degrees
  // Without odometry: constant-position noise per scan (x, y in m, heading in rad); the vehicle
  // moves up to 1.4 m and turns a few degrees per scan [C].
  std::vector<double> stds_q_no_odometry = {1.0, 1.0, 5.0 * std::numbers::pi / 180.0};
  // With odometry: the standard deviation of each scan's dead-reckoned motion, a floor plus a
  // share of the motion itself [C].
  double odometry_std_xy = 0.05;          // m
  double odometry_std_xy_ratio = 0.1;     // of the distance moved
  double odometry_std_heading_rad = 0.5 * std::numbers::pi / 180.0;
  double odometry_std_heading_ratio = 0.1;  // of the heading change
  double chi2_threshold = 0.99;  // individual compatibility test of JCBB / NN
  double time_budget_ms = 1000.0;
  int budget_iterations = 20;
};

std::vector<OptionIssue> check(const Ekf2dOptions& options);

}  // namespace relslam::eval
