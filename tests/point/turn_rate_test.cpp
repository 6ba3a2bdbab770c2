#include "relslam/point/turn_rate.hpp"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace relslam::point {
namespace {

Eigen::Matrix3d yaw(double degrees) {
  return Eigen::AngleAxisd(degrees * std::numbers::pi / 180.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
}

double angle_deg(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return std::acos(std::clamp(((a.transpose() * b).trace() - 1.0) / 2.0, -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

// A robot on an arc turning 0.25 degrees per iteration (the figure eight's arcs: about 0.23)
// keeps turning while one point is in view: 100 iterations on, the prediction is 25 degrees on,
// where keeping the latest rotation is 25 degrees off (density 5, seed 2: 23 degrees).
TEST(TurnRate, PredictsAConstantTurnOverAStretchWithoutRegisteredRotation) {
  TurnRate rate(30);
  for (int k = 0; k <= 40; ++k) rate.record(k, yaw(0.25 * k));
  EXPECT_NEAR(rate.rate().norm() * 180.0 / std::numbers::pi, 0.25, 1e-9);
  EXPECT_LT(angle_deg(yaw(0.25 * 40) * rate.turn(40, 140), yaw(0.25 * 140)), 1e-5);  // degrees: acos near 0
}

// The rate is measured over at least `window` iterations: before that there is none (the latest
// rotation is kept, as without a rate), and a single noisy registration right after a long gap
// does not become the rate over one iteration.
TEST(TurnRate, MeasuresOverAtLeastTheWindowAndForgetsOnClear) {
  TurnRate rate(30);
  for (int k = 0; k < 30; ++k) rate.record(k, yaw(0.25 * k));
  EXPECT_EQ(rate.turn(29, 129), Eigen::Matrix3d::Identity());
  rate.record(30, yaw(7.5));
  rate.record(31, yaw(7.75 + 2.0));  // 2 degrees of registration noise
  // Over the 30 iterations since 1: 9.5 / 30, not 2.25 over one iteration.
  EXPECT_NEAR(rate.rate().norm() * 180.0 / std::numbers::pi, 9.5 / 30.0, 1e-9);
  rate.clear();
  EXPECT_EQ(rate.turn(31, 131), Eigen::Matrix3d::Identity());
  TurnRate off(0);
  off.record(0, yaw(0));
  off.record(100, yaw(25));
  EXPECT_EQ(off.turn(100, 200), Eigen::Matrix3d::Identity());
}

}  // namespace
}  // namespace relslam::point
