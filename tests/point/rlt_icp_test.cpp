#include "relslam/point/rlt_icp.hpp"

#include "seeded_random.hpp"

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include <algorithm>

namespace relslam::point {
namespace {

Rigid3 random_motion(test::SeededRandom& rng, bool planar = false) {
  Eigen::Quaterniond q(rng.gaussian(), rng.gaussian(), rng.gaussian(), rng.gaussian());
  if (planar) q = Eigen::Quaterniond(Eigen::AngleAxisd(rng.uniform(-M_PI, M_PI), Eigen::Vector3d::UnitZ()));
  return Rigid3::from(q, {rng.uniform(-50, 50), rng.uniform(-50, 50), planar ? 0.0 : rng.uniform(-50, 50)});
}

// `n` points uniform in the cube [−half, half]³ appended to `a`, their images under `truth` to
// `b`, each image with Gaussian noise of σ `noise` per axis (none drawn when 0).
void cube_pairs(test::SeededRandom& rng, const Rigid3& truth, int n, double half, double noise,
                std::vector<Eigen::Vector3d>& a, std::vector<Eigen::Vector3d>& b) {
  for (int i = 0; i < n; ++i) {
    a.emplace_back(rng.uniform(-half, half), rng.uniform(-half, half), rng.uniform(-half, half));
    b.push_back(truth * a.back());
    if (noise > 0) b.back() += noise * Eigen::Vector3d(rng.gaussian(), rng.gaussian(), rng.gaussian());
  }
}

void expect_same_motion(const Rigid3& a, const Rigid3& b, const std::string& what) {
  EXPECT_LT((a.rotation - b.rotation).norm(), 1e-12) << what;
  EXPECT_LT((a.translation - b.translation).norm(), 1e-10) << what;
}

TEST(RltICP, RecoversRandomRigidMotionsExactlyFromNoiseFreePoints) {
  test::SeededRandom rng(101);
  for (int trial = 0; trial < 50; ++trial) {
    const Rigid3 truth = random_motion(rng);
    const int n = 3 + trial;
    std::vector<Eigen::Vector3d> a, b;
    for (int i = 0; i < n; ++i) {
      a.emplace_back(rng.uniform(-100, 100), rng.uniform(-5, 5), rng.uniform(0, 100));
      b.push_back(truth * a.back());
    }
    const auto fit = rlt_icp(a, b);
    ASSERT_TRUE(fit) << "trial " << trial;
    expect_same_motion(*fit, truth, "trial " + std::to_string(trial));
  }
}

TEST(RltICP, HandlesCoplanarSetsLikeVictoriaPark) {
  test::SeededRandom rng(102);
  for (bool planar_motion : {true, false})
    for (int trial = 0; trial < 20; ++trial) {
      const Rigid3 truth = random_motion(rng, planar_motion);
      std::vector<Eigen::Vector3d> a, b;
      for (int i = 0; i < 4 + trial; ++i) {
        a.emplace_back(rng.uniform(-40, 40), rng.uniform(-40, 40), 0.0);  // all in one plane
        b.push_back(truth * a.back());
      }
      const auto fit = rlt_icp(a, b);
      ASSERT_TRUE(fit);
      expect_same_motion(*fit, truth, "planar trial " + std::to_string(trial));
      EXPECT_NEAR(fit->rotation.determinant(), 1.0, 1e-12) << "a rotation, never a reflection";
    }
}

TEST(RltICP, RejectsFewerThanThreePairsAndCollinearPoints) {
  const std::vector<Eigen::Vector3d> two = {{0, 0, 0}, {1, 0, 0}};
  EXPECT_FALSE(rlt_icp(two, two));
  const std::vector<Eigen::Vector3d> line = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {5, 5, 5}};
  EXPECT_FALSE(rlt_icp(line, line));
  const std::vector<Eigen::Vector3d> three = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_FALSE(rlt_icp(three, two)) << "sizes differ";
  EXPECT_TRUE(rlt_icp(three, three));
}

TEST(RltICP, FitsNoisyPointsInTheLeastSquaresSense) {
  test::SeededRandom rng(103);
  const Rigid3 truth = random_motion(rng);
  std::vector<Eigen::Vector3d> a, b;
  cube_pairs(rng, truth, 2000, 50, 0.1, a, b);
  const auto fit = rlt_icp(a, b);
  ASSERT_TRUE(fit);
  // Rotation error ~ sigma / (spread·sqrt(n)) ≈ 0.1 / (29·45) ≈ 1e-4 rad.
  EXPECT_LT(Eigen::AngleAxisd(Eigen::Matrix3d(fit->rotation.transpose() * truth.rotation)).angle(), 1e-3);
}

// Two pairs fix b_T_a up to a rotation about their line; the prior supplies it. A
// robot on a floor (robot frame: +y up) errs in yaw: for a level line that error is removed
// exactly, so a prior whose yaw is off by any angle still gives the true motion.
TEST(RegisterTwoPoints, RemovesAPriorsYawErrorExactlyForALevelLine) {
  test::SeededRandom rng(104);
  const Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  for (int trial = 0; trial < 50; ++trial) {
    const Rigid3 truth{Eigen::AngleAxisd(rng.uniform(-M_PI, M_PI), up).toRotationMatrix(),
                       {rng.uniform(-50, 50), rng.uniform(-1, 1), rng.uniform(-50, 50)}};
    const Eigen::Vector3d a0(rng.uniform(-20, 20), 1.5, rng.uniform(-20, 20));
    const Eigen::Vector3d a1(rng.uniform(-20, 20), 1.5, rng.uniform(-20, 20));
    const Eigen::Matrix3d prior = Eigen::AngleAxisd(rng.uniform(-3, 3), up).toRotationMatrix() * truth.rotation;
    const auto fit = register_two_points(a0, a1, truth * a0, truth * a1, prior, up, std::sin(M_PI / 4));
    ASSERT_TRUE(fit) << "trial " << trial;
    expect_same_motion(*fit, truth, "trial " + std::to_string(trial));
  }
}

// The one free rotation, about the line, is the prior's: with a prior turned about the line the
// result is that prior (it maps the line already), and the pairs land on each other.
TEST(RegisterTwoPoints, TakesTheRotationAboutTheLineFromThePrior) {
  test::SeededRandom rng(105);
  const Rigid3 truth = random_motion(rng);
  const Eigen::Vector3d a0(1, 2, 0), a1(4, -2, 0.5);
  const Eigen::Vector3d b0 = truth * a0, b1 = truth * a1;
  const Eigen::Vector3d axis = (b1 - b0).normalized();
  const Eigen::Matrix3d prior = Eigen::AngleAxisd(0.3, axis).toRotationMatrix() * truth.rotation;
  const auto fit = register_two_points(a0, a1, b0, b1, prior, Eigen::Vector3d::UnitY(), 1.0);
  ASSERT_TRUE(fit);
  EXPECT_LT((fit->rotation - prior).norm(), 1e-12);
  EXPECT_LT((*fit * a0 - b0).norm(), 1e-12);
  EXPECT_LT((*fit * a1 - b1).norm(), 1e-12);
}

TEST(RegisterTwoPoints, RejectsASteepLineAndCoincidentPoints) {
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  const Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  const Eigen::Vector3d origin(0, 0, 0), steep(0.5, 1, 0), level(1, 0.2, 0);
  const double sine_45 = std::sin(M_PI / 4);
  EXPECT_FALSE(register_two_points(origin, steep, origin, steep, identity, up, sine_45)) << "63 degrees steep";
  EXPECT_TRUE(register_two_points(origin, level, origin, level, identity, up, sine_45)) << "11 degrees steep";
  EXPECT_FALSE(register_two_points(origin, origin, origin, level, identity, up, sine_45)) << "a's pair coincides";
  EXPECT_FALSE(register_two_points(origin, level, level, level, identity, up, sine_45)) << "b's pair coincides";
}

// Two-anchor groups average their rotation prior over their iterations: the chordal
// mean of noisy copies of one rotation comes back to it, far closer than a single copy.
TEST(MeanRotation, AveragesNoisyCopiesOfOneRotation) {
  test::SeededRandom rng(16);
  const Eigen::Matrix3d truth = random_motion(rng).rotation;
  EXPECT_LT((mean_rotation(truth) - truth).norm(), 1e-12) << "one rotation is its own mean";
  EXPECT_LT((mean_rotation(3.0 * truth) - truth).norm(), 1e-12) << "the scale of the sum does not matter";
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  double worst_single = 0;
  const int n = 200;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d axis(rng.gaussian(), rng.gaussian(), rng.gaussian());
    const Eigen::Matrix3d noisy = truth * Eigen::AngleAxisd(0.1, axis.normalized()).toRotationMatrix();
    worst_single = std::max(worst_single, Eigen::AngleAxisd(truth.transpose() * noisy).angle());
    sum += noisy;
  }
  const Eigen::Matrix3d mean = mean_rotation(sum);
  EXPECT_NEAR(mean.determinant(), 1.0, 1e-12);
  EXPECT_LT((mean.transpose() * mean - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  // Each copy is 0.1 rad off in a random direction; 200 of them average to ~0.1 / sqrt(200).
  EXPECT_NEAR(worst_single, 0.1, 1e-9);
  EXPECT_LT(Eigen::AngleAxisd(truth.transpose() * mean).angle(), 0.02);
}

// A registration rejected as a mismatch (a swap of two pairs) leaves the pose to the predicted
// rotation and the pairs' centroids: the swap does not move the centroid.
TEST(RegisterCentroids, PutsTheCentroidOnItsImageAndIgnoresASwap) {
  test::SeededRandom rng(17);
  const Rigid3 truth = random_motion(rng);
  std::vector<Eigen::Vector3d> a, b;
  cube_pairs(rng, truth, 4, 10, 0, a, b);
  expect_same_motion(register_centroids(a, b, truth.rotation), truth, "matched");
  std::swap(b[0], b[1]);
  expect_same_motion(register_centroids(a, b, truth.rotation), truth, "two pairs swapped");
  expect_same_motion(register_centroids(std::span(a).first(1), std::span(b).subspan(2, 1), truth.rotation),
                     register_one_point(a[0], b[2], truth.rotation), "one pair");
}

// The provisional chain's rotation is part of the way from the prediction to the registration.
TEST(InterpolateRotation, GoesTheGivenShareOfTheWay) {
  const Eigen::Matrix3d from = Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Matrix3d to = Eigen::AngleAxisd(1.2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  EXPECT_LT((interpolate_rotation(from, to, 0.0) - from).norm(), 1e-12);
  EXPECT_LT((interpolate_rotation(from, to, 1.0) - to).norm(), 1e-12);
  EXPECT_LT((interpolate_rotation(from, to, 0.3) - Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitY()).toRotationMatrix())
                .norm(),
            1e-12);
}

}  // namespace
}  // namespace relslam::point
