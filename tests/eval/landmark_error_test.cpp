#include "relslam/eval/metrics/landmark_error.hpp"

#include "relslam/sim/random.hpp"

#include <gtest/gtest.h>

#include <map>

namespace relslam::eval {
namespace {

TEST(LandmarkErrorTracker, IncrementalSumMatchesBruteForceWithMovingTruth) {
  sim::RandomSequence rng(801, sim::Stream::Field);
  LandmarkTruth truth;
  for (int i = 0; i < 300; ++i)
    truth.positions.emplace_back(rng.uniform(-50, 50), rng.uniform(-5, 5), rng.uniform(-50, 50));
  truth.dynamic_ids = {3, 77};
  auto dynamic_position = [&](int id, int k) {
    Eigen::Vector3d p = truth.positions[id];
    p.x() += 0.1 * k;  // movers drift along x
    return p;
  };
  LandmarkErrorTracker tracker(truth);

  std::map<int, Eigen::Vector3d> map;  // the estimate: id -> position
  for (int k = 0; k < 100; ++k) {
    std::vector<int> changed;
    for (int n = 0; n < 20; ++n) {
      const int id = static_cast<int>(rng.below(150));
      changed.push_back(id);
      if (rng.uniform() < 0.8)
        map[id] = Eigen::Vector3d(rng.uniform(-50, 50), rng.uniform(-5, 5), rng.uniform(-50, 50));
      else
        map.erase(id);
    }
    const std::vector<Eigen::Vector3d> movers = {dynamic_position(3, k), dynamic_position(77, k)};
    tracker.update(movers, changed, [&](int id) -> std::optional<Eigen::Vector3d> {
      const auto it = map.find(id);
      if (it == map.end()) return std::nullopt;
      return it->second;
    });
    double expected = 0;
    for (const auto& [id, p] : map) {
      double nearest = 1e300;
      for (int t = 0; t < 300; ++t) {
        const bool moving = t == 3 || t == 77;
        nearest = std::min(nearest, (p - (moving ? dynamic_position(t, k) : truth.positions[t])).norm());
      }
      expected += nearest;
      ASSERT_NEAR(tracker.error_of(id), nearest, 1e-12);
    }
    ASSERT_EQ(tracker.count(), static_cast<int>(map.size()));
    ASSERT_NEAR(tracker.sum(), expected, 1e-9) << "k " << k;
  }
}

TEST(LandmarkErrorTracker, AFrameWithoutTheMoversPositionsIsALogicError) {
  LandmarkTruth truth;
  truth.positions = {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()};
  truth.dynamic_ids = {1};
  LandmarkErrorTracker tracker(truth);
  const auto at_origin = [](int) { return std::optional<Eigen::Vector3d>(Eigen::Vector3d::Zero()); };
  EXPECT_THROW(tracker.update({}, {0}, at_origin), std::logic_error);
  tracker.update({Eigen::Vector3d(0.5, 0, 0)}, {0}, at_origin);
  EXPECT_DOUBLE_EQ(tracker.sum(), 0.0);
  EXPECT_EQ(tracker.nearest(Eigen::Vector3d(0.4, 0, 0), {Eigen::Vector3d(0.5, 0, 0)}).first, 1);
}

}  // namespace
}  // namespace relslam::eval
