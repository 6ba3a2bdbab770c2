#include "relslam/plane/rlt_map_builder.hpp"

#include <gtest/gtest.h>

namespace relslam::plane {
namespace {

constexpr double kSameLength = 0.02;  // τ_len

MapPlane entry(double length, KeyPoint key_point, bool size_static) {
  MapPlane e;
  e.mapped = true;
  e.length = length;
  e.key_point = key_point;
  e.size_static = size_static;
  return e;
}

// A wall mapped at 3.95 from its left end, then seen 4 long: the entry is a piece, and only its
// left end is the wall's. Growing an observation from the right end onto it would put the pose
// off by the 0.05 never seen (Map D, large frustum, wall 2).
TEST(MapPlane, APieceShorterThanWhatWasSeenHoldsOnlyItsKeyPointEnd) {
  const MapPlane piece = entry(3.95, KeyPoint::Left, false);
  EXPECT_TRUE(piece.holds_end(KeyPoint::Left, 4.0, kSameLength));
  EXPECT_FALSE(piece.holds_end(KeyPoint::Right, 4.0, kSameLength));
}

TEST(MapPlane, AnEntryAsLongAsAnythingSeenIsTakenAsWhole) {
  // Never seen longer (within τ_len): both ends count, as a wall that grew into view whole.
  EXPECT_TRUE(entry(4.0, KeyPoint::Left, false).holds_end(KeyPoint::Right, 4.0 + 0.5 * kSameLength, kSameLength));
  // A comparison that saw it keep its size placed both ends.
  EXPECT_TRUE(entry(3.95, KeyPoint::Left, true).holds_end(KeyPoint::Right, 4.0, kSameLength));
  // Placed without a key point (full-size observations, part 1): nothing to tell the ends apart.
  EXPECT_TRUE(entry(3.95, KeyPoint::None, false).holds_end(KeyPoint::Right, 4.0, kSameLength));
}

}  // namespace
}  // namespace relslam::plane
