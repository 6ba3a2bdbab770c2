#include "relslam/plane/rlt_plane_interval.hpp"
#include "relslam/plane/rlt_interval.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace relslam::plane {
namespace {

RltPlaneInterval from_iterations(std::initializer_list<int> iterations) {
  RltPlaneInterval interval;
  for (int t : iterations) interval.add(t);
  return interval;
}

TEST(RltInterval, SizeMergeAndShrink) {
  const RltInterval a{3, 7}, b{6, 10}, c{12, 11};
  EXPECT_EQ(a.size(), 5);
  EXPECT_TRUE(c.empty());
  EXPECT_EQ(c.size(), 0);
  EXPECT_TRUE(a.in_interval(3));
  EXPECT_TRUE(a.in_interval(7));
  EXPECT_FALSE(a.in_interval(8));
  EXPECT_EQ(a.merge(b).start, 3);
  EXPECT_EQ(a.merge(b).end, 10);
  EXPECT_EQ(a.merge(c).size(), 5);
  EXPECT_EQ(a.shrink(b).start, 6);
  EXPECT_EQ(a.shrink(b).end, 7);
  EXPECT_TRUE(a.shrink(RltInterval{8, 9}).empty());
}

TEST(RltPlaneInterval, AMissingIterationStartsANewRun) {
  const RltPlaneInterval interval = from_iterations({1, 2, 3, 5, 6, 9});
  ASSERT_EQ(interval.runs().size(), 3u);
  EXPECT_EQ(interval.runs()[0].end, 3);
  EXPECT_EQ(interval.runs()[1].start, 5);
  EXPECT_EQ(interval.total_size(), 6);
  EXPECT_TRUE(interval.in_interval(5));
  EXPECT_FALSE(interval.in_interval(4));
  EXPECT_FALSE(interval.in_interval(10));
  EXPECT_FALSE(interval.in_interval(0));
  EXPECT_EQ(interval.first(), 1);
  EXPECT_EQ(interval.last(), 9);
}

TEST(RltPlaneInterval, IterationsMustIncrease) {
  RltPlaneInterval interval = from_iterations({4, 5});
  EXPECT_THROW(interval.add(5), std::logic_error);
  EXPECT_THROW(interval.add(2), std::logic_error);
}

TEST(RltPlaneInterval, MinimumIntervalIntersectsMultiRunLists) {
  // Runs [0,9] [20,29] [40,49] against [5,24] [45,60].
  RltPlaneInterval a, b;
  for (int start : {0, 20, 40})
    for (int t = start; t < start + 10; ++t) a.add(t);
  for (int t = 5; t <= 24; ++t) b.add(t);
  for (int t = 45; t <= 60; ++t) b.add(t);
  RltPlaneInterval both;
  RltPlaneInterval::minimum_interval(a, b, both);
  ASSERT_EQ(both.runs().size(), 3u);
  EXPECT_EQ(both.runs()[0].start, 5);
  EXPECT_EQ(both.runs()[0].end, 9);
  EXPECT_EQ(both.runs()[1].start, 20);
  EXPECT_EQ(both.runs()[1].end, 24);
  EXPECT_EQ(both.runs()[2].start, 45);
  EXPECT_EQ(both.runs()[2].end, 49);
  EXPECT_EQ(both.total_size(), 15);
  EXPECT_EQ(RltPlaneInterval::common_size(a, b), 15);
  EXPECT_EQ(RltPlaneInterval::common_size(b, a), 15);
  EXPECT_EQ(RltPlaneInterval::common_size(a, RltPlaneInterval{}), 0);
}

}  // namespace
}  // namespace relslam::plane
