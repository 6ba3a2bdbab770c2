// The Ceres global relaxation on synthetic chains of groups with a known truth.
#include "relslam/relax/ceres_relaxation.hpp"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <vector>

namespace relslam::relax {
namespace {

using point::GroupTie;
using point::RelaxationProblem;

// A loop of groups on a circle of radius 10 (a figure-eight's lobe): group i sees
// kPointsPerGroup world points, the first kShared of them also seen by group i-1 (group 0's by
// the last group: the loop closure). Relative positions are exact.
constexpr int kGroups = 20;
constexpr int kPointsPerGroup = 8;
constexpr int kShared = 4;
constexpr double kRadius = 10.0;

struct Chain {
  std::vector<Rigid3> truth;                 // world_T_group
  std::vector<std::vector<Eigen::Vector3d>> world;  // per group: its points in the world
  RelaxationProblem problem;
};

Rigid3 truth_pose(int i) {
  const double a = 2 * std::numbers::pi * i / kGroups;
  return {rotation_about(Eigen::Vector3d::UnitZ(), a + std::numbers::pi / 2),
          Eigen::Vector3d(kRadius * std::cos(a), kRadius * std::sin(a), 0.1 * i)};
}

Chain make_chain(double loss_scale) {
  Chain c;
  for (int i = 0; i < kGroups; ++i) c.truth.push_back(truth_pose(i));
  // Point j of group i, in group i's frame: spread over a few units, off the plane.
  auto local = [](int i, int j) {
    return Eigen::Vector3d(1.5 * std::cos(j + 0.3 * i), 1.5 * std::sin(1.7 * j), 0.4 * (j % 3) - 0.4);
  };
  c.world.resize(kGroups);
  for (int i = 0; i < kGroups; ++i)
    for (int j = 0; j < kPointsPerGroup; ++j) c.world[i].push_back(c.truth[i] * local(i, j));
  // The last kShared points of group i are the first kShared of group i+1 (mod kGroups).
  c.problem.loss_scale = loss_scale;
  for (int i = 0; i < kGroups; ++i) {
    const int next = (i + 1) % kGroups;
    for (int j = 0; j < kShared; ++j) {
      const Eigen::Vector3d p_world = c.world[i][kPointsPerGroup - kShared + j];
      c.world[next][j] = p_world;
      c.problem.ties.push_back({i, c.truth[i].inverse() * p_world, next, c.truth[next].inverse() * p_world});
    }
  }
  c.problem.world_T_group = c.truth;
  c.problem.fixed.assign(kGroups, false);
  c.problem.fixed[0] = true;  // the root
  return c;
}

double translation_error(const Rigid3& a, const Rigid3& b) { return (a.translation - b.translation).norm(); }
double rotation_error_rad(const Rigid3& a, const Rigid3& b) {
  return Eigen::AngleAxisd(a.rotation.transpose() * b.rotation).angle();
}

// Largest world displacement of any group's points between two sets of transforms.
double largest_point_motion(const Chain& c, const std::vector<Rigid3>& moved) {
  double worst = 0;
  for (int i = 0; i < kGroups; ++i)
    for (const Eigen::Vector3d& p_world : c.world[i]) {
      const Eigen::Vector3d p_group = c.truth[i].inverse() * p_world;
      worst = std::max(worst, (moved[i] * p_group - p_world).norm());
    }
  return worst;
}

// Solver precision: the tolerances are 1e-14 relative; the map spans ~20 units.
constexpr double kSolverPrecision = 1e-7;

TEST(CeresRelaxation, ChainWithInjectedDriftReturnsToTheTruth) {
  Chain c = make_chain(0.3);
  // Odometry-like drift: every link adds a small rotation and offset, so group i is off by
  // i links' worth (up to ~2 units and 0.2 rad at the loop's end) while every link's own ties
  // still agree: only the loop closure (last group to root) sees the error.
  const Rigid3 drift{rotation_about(Eigen::Vector3d(0.3, 0.2, 1).normalized(), 0.01), Eigen::Vector3d(0.05, -0.03, 0.02)};
  Rigid3 accumulated = Rigid3::identity();
  for (int i = 1; i < kGroups; ++i) {
    accumulated = accumulated * drift;
    c.problem.world_T_group[i] = c.truth[i] * accumulated;
  }
  ASSERT_GT(largest_point_motion(c, c.problem.world_T_group), 1.0) << "the drift must be visible";
  const point::RelaxationReport report = solve_relaxation(c.problem);
  ASSERT_TRUE(report.solved);
  EXPECT_LT(report.final_cost, 1e-12) << "initial " << report.initial_cost;
  for (int i = 0; i < kGroups; ++i) {
    EXPECT_LT(translation_error(c.problem.world_T_group[i], c.truth[i]), kSolverPrecision) << "group " << i;
    EXPECT_LT(rotation_error_rad(c.problem.world_T_group[i], c.truth[i]), kSolverPrecision) << "group " << i;
  }
}

TEST(CeresRelaxation, ConsistentGroupsDoNotMove) {
  Chain c = make_chain(0.3);
  solve_relaxation(c.problem);
  EXPECT_LT(largest_point_motion(c, c.problem.world_T_group), 1e-12);
}

// A wrong tie (a global match to a point 5 units away) between groups 5 and 15, opposite on the
// loop. Under the Cauchy loss its pull never exceeds scale/2 = 0.15 however wrong it is. Between
// groups 5 and 15 run two paths of 10 links each, each link held by 4 correct ties of unit
// stiffness, so in translation the two groups yield (s/2)·10/(2·4) ≈ 0.19 towards each other;
// rotation lets the lever arm (1.5 units over a 10-unit radius) add a little: 0.3 (= the scale)
// bounds any point's motion. A quadratic loss spreads the wrong 5 units over the loop instead.
constexpr double kWrongMatchBound = 0.3;

TEST(CeresRelaxation, OneWrongTieMovesTheMapByLessThanTheLossScale) {
  for (const double scale : {0.3, 1e6}) {
    Chain c = make_chain(scale);
    const Eigen::Vector3d p_world = c.world[5][0];
    c.problem.ties.push_back({5, c.truth[5].inverse() * p_world, 15,
                              c.truth[15].inverse() * (p_world + Eigen::Vector3d(3, 4, 0))});
    ASSERT_TRUE(solve_relaxation(c.problem).solved);
    const double moved = largest_point_motion(c, c.problem.world_T_group);
    if (scale < 1)
      EXPECT_LT(moved, kWrongMatchBound) << "robust loss";
    else
      EXPECT_GT(moved, kWrongMatchBound) << "an (almost) quadratic loss is dragged: the bound means something";
  }
}

TEST(CeresRelaxation, OnlyFixedGroupsLeaveTheProblemAsGiven) {
  Chain c = make_chain(0.3);
  c.problem.fixed.assign(kGroups, true);
  c.problem.world_T_group[3].translation.x() += 1;
  EXPECT_FALSE(solve_relaxation(c.problem).solved);
  EXPECT_EQ(c.problem.world_T_group[3].translation.x(), c.truth[3].translation.x() + 1);
}

TEST(CeresRelaxation, SameProblemGivesIdenticalBits) {
  Chain a = make_chain(0.3), b = make_chain(0.3);
  for (Chain* c : {&a, &b})
    for (int i = 1; i < kGroups; ++i) c->problem.world_T_group[i].translation += Eigen::Vector3d(0.01 * i, 0, 0);
  solve_relaxation(a.problem);
  solve_relaxation(b.problem);
  for (int i = 0; i < kGroups; ++i) {
    EXPECT_EQ(a.problem.world_T_group[i].translation, b.problem.world_T_group[i].translation) << i;
    EXPECT_EQ(a.problem.world_T_group[i].rotation, b.problem.world_T_group[i].rotation) << i;
  }
}

}  // namespace
}  // namespace relslam::relax
