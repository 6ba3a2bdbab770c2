#include "relslam/sim/simulator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace relslam::sim {
namespace {

SimOptions short_run(double density = 25, int iterations = 300) {
  SimOptions o;
  o.density = density;
  o.iterations = iterations;
  return o;
}

bool same_bits(const SimFrame& a, const SimFrame& b) {
  if (a.observation.points.size() != b.observation.points.size()) return false;
  if (a.truth.landmark_ids != b.truth.landmark_ids) return false;
  return std::memcmp(a.observation.points.data(), b.observation.points.data(),
                     a.observation.points.size() * sizeof(Eigen::Vector3d)) == 0;
}

TEST(Simulator, SameSeedGivesBitIdenticalFrames) {
  const Simulator a(short_run(), 7), b(short_run(), 7);
  for (int k = 0; k < a.iterations(); ++k) ASSERT_TRUE(same_bits(a.frame(k), b.frame(k))) << "k " << k;
}

TEST(Simulator, FramesCanBeProducedInAnyOrder) {
  const Simulator sim(short_run(), 7);
  const SimFrame late = sim.frame(250);
  for (int k = 0; k < 250; ++k) sim.frame(k);
  EXPECT_TRUE(same_bits(late, sim.frame(250)));
}

TEST(Simulator, DifferentSeedGivesDifferentNoise) {
  const Simulator a(short_run(), 7), b(short_run(), 8);
  EXPECT_FALSE(same_bits(a.frame(10), b.frame(10)));
}

TEST(Simulator, NoiseFreeObservationsAreExactRobotFramePoints) {
  SimOptions o = short_run(100, 400);
  o.noise_sigma = 0;
  const Simulator sim(o, 1);
  for (int k = 0; k < sim.iterations(); k += 37) {
    const SimFrame f = sim.frame(k);
    std::vector<int> expected_ids;
    for (int id = 0; id < sim.world().size(); ++id)
      if (o.frustum.contains(f.truth.world_T_robot.inverse_apply(sim.world().position(id, k))))
        expected_ids.push_back(id);
    std::vector<int> ids = f.truth.landmark_ids;
    std::sort(ids.begin(), ids.end());
    EXPECT_EQ(ids, expected_ids) << "k " << k;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const Eigen::Vector3d truth =
          f.truth.world_T_robot.inverse_apply(sim.world().position(f.truth.landmark_ids[i], k));
      EXPECT_LT((f.observation.points[i] - truth).norm(), 1e-12) << "k " << k;
    }
  }
}

TEST(Simulator, NoiseIsZeroMeanWithTheConfiguredSigmaOnEachAxis) {
  SimOptions o = short_run(100, 600);
  o.noise_sigma = 0.1;
  const Simulator sim(o, 3);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero(), sum2 = Eigen::Vector3d::Zero();
  int n = 0;
  for (int k = 0; k < sim.iterations(); ++k) {
    const SimFrame f = sim.frame(k);
    for (std::size_t i = 0; i < f.observation.points.size(); ++i) {
      const Eigen::Vector3d truth =
          f.truth.world_T_robot.inverse_apply(sim.world().position(f.truth.landmark_ids[i], k));
      // Only points well inside the frustum: culling the noisy point biases those at the faces.
      if (!o.frustum.prepare().may_contain(truth, -1.0)) continue;
      const Eigen::Vector3d e = f.observation.points[i] - truth;
      sum += e;
      sum2 += e.cwiseProduct(e);
      ++n;
    }
  }
  ASSERT_GT(n, 30000);
  for (int axis = 0; axis < 3; ++axis) {
    const double mean = sum[axis] / n, sigma = std::sqrt(sum2[axis] / n - mean * mean);
    EXPECT_NEAR(mean, 0.0, 5 * 0.1 / std::sqrt(n)) << "axis " << axis;
    EXPECT_NEAR(sigma, 0.1, 5 * 0.1 / std::sqrt(2.0 * n)) << "axis " << axis;
  }
}

TEST(Simulator, RangeNoiseGrowsWithDistance) {
  SimOptions o = short_run(100, 400);
  o.range_noise = true;
  const Simulator sim(o, 4);
  double near2 = 0, far2 = 0;
  int near_n = 0, far_n = 0;
  for (int k = 0; k < sim.iterations(); k += 2) {
    const SimFrame f = sim.frame(k);
    for (std::size_t i = 0; i < f.observation.points.size(); ++i) {
      const Eigen::Vector3d truth =
          f.truth.world_T_robot.inverse_apply(sim.world().position(f.truth.landmark_ids[i], k));
      const double e2 = (f.observation.points[i] - truth).squaredNorm() / 3.0;
      if (truth.norm() < 20) near2 += e2, ++near_n;
      if (truth.norm() > 80) far2 += e2, ++far_n;
    }
  }
  ASSERT_GT(near_n, 1000);
  ASSERT_GT(far_n, 1000);
  // sigma(r) = 0.1 (1 + r/100): about 0.11-0.12 near, 0.18-0.24 far.
  EXPECT_GT(std::sqrt(far2 / far_n) / std::sqrt(near2 / near_n), 1.4);
}

TEST(Simulator, OutputOrderIsShuffled) {
  const Simulator sim(short_run(100, 1), 5);
  const auto& ids = sim.frame(0).truth.landmark_ids;
  ASSERT_GT(ids.size(), 50u);
  int ascending = 0;
  for (std::size_t i = 1; i < ids.size(); ++i) ascending += ids[i] > ids[i - 1];
  // A random order has about half its neighbours ascending; id order would have all.
  EXPECT_LT(ascending, static_cast<int>(ids.size() * 3 / 4));
  EXPECT_GT(ascending, static_cast<int>(ids.size() / 4));
}

TEST(Simulator, DynamicPointsAreSeenAtTheirMovingPositions) {
  SimOptions o = short_run(25, 300);
  o.noise_sigma = 0;
  o.dynamic.count = 2;
  const Simulator sim(o, 6);
  const std::vector<int> movers = sim.world().dynamic_ids();
  ASSERT_EQ(movers.size(), 2u);
  int seen = 0;
  for (int k = 0; k < sim.iterations(); k += 5) {
    const SimFrame f = sim.frame(k);
    for (std::size_t i = 0; i < f.truth.landmark_ids.size(); ++i) {
      const int id = f.truth.landmark_ids[i];
      if (!sim.world().is_dynamic(id)) continue;
      const Eigen::Vector3d expected = f.truth.world_T_robot.inverse_apply(sim.world().position(id, k));
      EXPECT_LT((f.observation.points[i] - expected).norm(), 1e-12);
      ++seen;
    }
  }
  EXPECT_GT(seen, 20);
}

TEST(Simulator, InvalidOptionsThrowNamingTheField) {
  SimOptions o;
  o.density = -1;
  try {
    Simulator(o, 1);
    FAIL();
  } catch (const OptionError& e) {
    EXPECT_EQ(e.field(), "density");
  }
}

}  // namespace
}  // namespace relslam::sim
