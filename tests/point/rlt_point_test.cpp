#include "relslam/point/rlt_point.hpp"

#include <gtest/gtest.h>

namespace relslam::point {
namespace {

TEST(ObservationRing, WrapsAroundKeepingTheNewestAndLooksUpByIteration) {
  ObservationRing ring(8);
  for (int it = 0; it < 40; it += 2) ring.push({Eigen::Vector3d(it, 0, 0), it});
  EXPECT_EQ(ring.size(), 8);
  EXPECT_EQ(ring[0].iteration, 24) << "oldest kept";
  EXPECT_EQ(ring.latest().iteration, 38);
  for (int i = 1; i < ring.size(); ++i) EXPECT_GT(ring[i].iteration, ring[i - 1].iteration);
  ASSERT_NE(ring.at(30), nullptr);
  EXPECT_EQ(ring.at(30)->p.x(), 30);
  EXPECT_EQ(ring.at(31), nullptr) << "never observed";
  EXPECT_EQ(ring.at(22), nullptr) << "overwritten";
  EXPECT_EQ(ring.lower_bound(25), 1);
  EXPECT_EQ(ring.lower_bound(100), 8);
}

TEST(ObservationRing, RefusesObservationsOutOfOrder) {
  ObservationRing ring(4);
  ring.push({Eigen::Vector3d::Zero(), 3});
  EXPECT_THROW(ring.push({Eigen::Vector3d::Zero(), 3}), std::logic_error);
}

TEST(Point, CompareScoresFromHundredToZeroAndMinusOneOutside) {
  const Point a{{0, 0, 0}, 10}, b{{0.5, 0, 0}, 11}, far{{2, 0, 0}, 11}, late{{0, 0, 0}, 20};
  EXPECT_EQ(compare(a, a, 1.0, 3), 100);
  EXPECT_EQ(compare(a, b, 1.0, 3), 50);
  EXPECT_EQ(compare(a, far, 1.0, 3), -1);
  EXPECT_EQ(compare(a, late, 1.0, 3), -1) << "iterations too far apart";
}

}  // namespace
}  // namespace relslam::point
