#include "relslam/eval/metrics/trajectory_error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace relslam::eval {
namespace {

// A curving, climbing path so that alignment has something to find.
std::vector<Rigid3> spiral(int n) {
  std::vector<Rigid3> path;
  for (int k = 0; k < n; ++k) {
    const double a = 0.1 * k;
    path.push_back({rotation_about(Eigen::Vector3d::UnitY(), a), {5 * std::sin(a), 0.2 * k, 5 * std::cos(a)}});
  }
  return path;
}

TEST(TrajectoryError, IsZeroForTheTruthItself) {
  const auto truth = spiral(50);
  const TrajectoryError e = trajectory_error(truth, truth);
  EXPECT_EQ(e.ate_rmse, 0.0);
  EXPECT_NEAR(e.ate_rmse_aligned, 0.0, 1e-12);
  EXPECT_NEAR(e.rpe_translation_rmse, 0.0, 1e-12);
  EXPECT_NEAR(e.rpe_rotation_rmse_deg, 0.0, 1e-6);
}

TEST(TrajectoryError, AlignmentRemovesAWholeFrameOffsetThatRelativeErrorNeverSees) {
  const auto truth = spiral(50);
  const Rigid3 offset{rotation_about(Eigen::Vector3d(1, 2, 3).normalized(), 0.4), {3, -1, 2}};
  std::vector<Rigid3> estimate;
  for (const Rigid3& t : truth) estimate.push_back(offset * t);
  const TrajectoryError e = trajectory_error(estimate, truth);
  EXPECT_GT(e.ate_rmse, 1.0);
  EXPECT_NEAR(e.ate_rmse_aligned, 0.0, 1e-9);
  EXPECT_NEAR(e.rpe_translation_rmse, 0.0, 1e-9);
  EXPECT_NEAR(e.rpe_rotation_rmse_deg, 0.0, 1e-5);
}

TEST(TrajectoryError, ConstantShiftIsTheUnalignedError) {
  const auto truth = spiral(20);
  std::vector<Rigid3> estimate = truth;
  for (Rigid3& p : estimate) p.translation += Eigen::Vector3d(0.3, 0, 0.4);
  EXPECT_NEAR(trajectory_error(estimate, truth).ate_rmse, 0.5, 1e-12);
}

TEST(TrajectoryError, OneBadStepShowsInTheRelativeError) {
  const auto truth = spiral(11);  // 10 steps
  std::vector<Rigid3> estimate = truth;
  // From pose 5 on, everything is shifted by 1 along x: one step of 10 is wrong by 1.
  for (std::size_t k = 5; k < estimate.size(); ++k) estimate[k].translation.x() += 1.0;
  const TrajectoryError e = trajectory_error(estimate, truth);
  EXPECT_NEAR(e.rpe_translation_rmse, std::sqrt(1.0 / 10), 1e-12);
  EXPECT_NEAR(e.rpe_rotation_rmse_deg, 0.0, 1e-5);
  EXPECT_NEAR(e.ate_rmse, std::sqrt(6.0 / 11), 1e-12);
}

TEST(TrajectoryError, PairsByIndexAndIgnoresTheLongerTail) {
  const auto truth = spiral(30);
  std::vector<Rigid3> estimate(truth.begin(), truth.begin() + 10);
  EXPECT_EQ(trajectory_error(estimate, truth).ate_rmse, 0.0);
  EXPECT_EQ(trajectory_error({}, truth).ate_rmse, 0.0);
}

}  // namespace
}  // namespace relslam::eval
