#include "relslam/sim/frustum.hpp"

#include "relslam/sim/random.hpp"

#include <gtest/gtest.h>

namespace relslam::sim {
namespace {

TEST(Frustum, BoundariesAreInclusive) {
  const Frustum f;  // near 1, far 100, ±45°, |y| <= 5
  EXPECT_TRUE(f.contains({0, 0, 1}));
  EXPECT_TRUE(f.contains({0, 0, 100}));
  const double side = 50 * std::tan(f.half_angle_rad);  // tan(45°) is not exactly 1 in doubles
  EXPECT_TRUE(f.contains({side, 5, 50}));               // on the side face and the top
  EXPECT_TRUE(f.contains({-side, -5, 50}));
}

TEST(Frustum, PointsJustOutsideEachFaceAreCulled) {
  const Frustum f;
  constexpr double e = 1e-9;
  EXPECT_FALSE(f.contains({0, 0, 1 - e}));
  EXPECT_FALSE(f.contains({0, 0, 100 + e}));
  EXPECT_FALSE(f.contains({50 + 1e-6, 0, 50}));
  EXPECT_FALSE(f.contains({-50 - 1e-6, 0, 50}));
  EXPECT_FALSE(f.contains({0, 5 + e, 50}));
  EXPECT_FALSE(f.contains({0, -5 - e, 50}));
  EXPECT_FALSE(f.contains({0, 0, -10})) << "behind the robot";
}

TEST(Frustum, RangeCapCutsTheCorners) {
  Frustum f;
  EXPECT_TRUE(f.contains({90, 0, 95}));
  f.far_cap = FarCap::Range;
  EXPECT_FALSE(f.contains({90, 0, 95})) << "130 units away";
  EXPECT_TRUE(f.contains({0, 0, 99.9}));
  EXPECT_DOUBLE_EQ(f.max_range(), 100.0);
}

TEST(Frustum, MayContainNeverMissesAPointThatNoiseCouldBringIn) {
  const Frustum f;
  const Frustum::Prepared prepared = f.prepare();
  RandomSequence rng(11, Stream::Field);
  constexpr double kMargin = 1.0;
  int tested = 0;
  for (int i = 0; i < 200000; ++i) {
    const Eigen::Vector3d q(rng.uniform(-120, 120), rng.uniform(-10, 10), rng.uniform(-10, 110));
    if (prepared.may_contain(q, kMargin)) continue;
    // q was culled: no point within kMargin of it may be inside.
    Eigen::Vector3d d(rng.gaussian(), rng.gaussian(), rng.gaussian());
    d *= rng.uniform(0, kMargin) / d.norm();
    ASSERT_FALSE(f.contains(q + d)) << "q = " << q.transpose() << " d = " << d.transpose();
    ++tested;
  }
  EXPECT_GT(tested, 10000);
}

TEST(Frustum, MaxRangeBoundsEveryVisiblePoint) {
  const Frustum f;
  RandomSequence rng(12, Stream::Field);
  for (int i = 0; i < 100000; ++i) {
    const Eigen::Vector3d p(rng.uniform(-100, 100), rng.uniform(-5, 5), rng.uniform(0, 100));
    if (f.contains(p)) {
      ASSERT_LE(p.norm(), f.max_range());
    }
  }
  EXPECT_NEAR(f.max_range(), std::sqrt(100.0 * 100 + 100 * 100 + 25), 1e-12);
}

}  // namespace
}  // namespace relslam::sim
