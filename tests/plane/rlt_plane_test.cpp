#include "relslam/plane/rlt_plane.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace relslam::plane {
namespace {

PlaneObject seen_at(int iteration) { return {{1, 0}, {1.0 + iteration, 0}, 0.0, 2.5, iteration}; }

TEST(RltPlane, GetPlaneFindsEveryStoredIterationAcrossWrapAround) {
  // Capacity 7, iterations 0, 2, 4, …, 38 with a pause: the array has wrapped several times and
  // its oldest kept observation sits in the middle of the physical storage.
  RltPlane plane(0, seen_at(0), 7);
  for (int t = 2; t <= 38; t += 2) plane.add(seen_at(t == 20 ? 21 : t));
  ASSERT_EQ(plane.size(), 7);
  EXPECT_EQ(plane[0].iteration, 26);
  EXPECT_EQ(plane.latest().iteration, 38);
  for (int t = 0; t <= 40; ++t) {
    const PlaneObject* found = plane.get_plane(t);
    const bool stored = t >= 26 && t <= 38 && t % 2 == 0;
    ASSERT_EQ(found != nullptr, stored) << "iteration " << t;
    if (found) {
      EXPECT_EQ(found->iteration, t);
    }
  }
  EXPECT_EQ(plane.lower_bound(27), 1);  // 28 is the second kept
  EXPECT_EQ(plane.lower_bound(0), 0);
  EXPECT_EQ(plane.lower_bound(39), 7);
  for (int i = 1; i < plane.size(); ++i) EXPECT_LT(plane[i - 1].iteration, plane[i].iteration);
}

TEST(RltPlane, LongestSeenRemembersAnOverwrittenObservation) {
  // A wall growing into view and leaving it again: lengths 1, 4, 2, 1 in a store of two.
  const auto seen = [](double length, int iteration) { return PlaneObject{{1, 0}, {1 + length, 0}, 0.0, 2.5, iteration}; };
  RltPlane plane(0, seen(1, 0), 2);
  EXPECT_EQ(plane.longest_seen(), 1.0);
  plane.add(seen(4, 1));
  plane.add(seen(2, 2));
  plane.add(seen(1, 3));
  ASSERT_EQ(plane[0].iteration, 2);  // the 4-long observation is gone from the store
  EXPECT_EQ(plane.longest_seen(), 4.0);
}

TEST(RltPlane, KeepsTheFirstObservationAndTheWholeIntervalAfterOverwriting) {
  RltPlane plane(3, seen_at(5), 2);
  for (int t = 6; t <= 9; ++t) plane.add(seen_at(t));
  EXPECT_EQ(plane.first_observation().iteration, 5);
  EXPECT_EQ(plane.created_iteration(), 5);
  EXPECT_EQ(plane.readings(), 5);
  EXPECT_EQ(plane.intervals().runs().size(), 1u);
  EXPECT_EQ(plane.size(), 2);
  EXPECT_EQ(plane.get_plane(5), nullptr);
}

TEST(RltPlane, RejectsAnObservationThatIsNotNewer) {
  RltPlane plane(0, seen_at(4), 10);
  EXPECT_THROW(plane.add(seen_at(4)), std::logic_error);
  EXPECT_THROW(plane.add(seen_at(1)), std::logic_error);
}

TEST(RltPlane, MembershipsAreFoundByGroup) {
  RltPlane plane(0, seen_at(0), 10);
  plane.join(2, 7).valid = true;
  plane.join(5, 9);
  ASSERT_NE(plane.ref(2), nullptr);
  EXPECT_TRUE(plane.ref(2)->valid);
  EXPECT_EQ(plane.ref(5)->join_iteration, 9);
  EXPECT_EQ(plane.ref(4), nullptr);
  EXPECT_THROW(plane.join(2, 10), std::logic_error);
}

}  // namespace
}  // namespace relslam::plane
