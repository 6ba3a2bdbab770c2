// Rule 36 (RltXPointRef::DoBackupCheck, thesis 4.4.3.5; thesis 4.3.7.3) on constructed references:
// which of the current comparison and the pair's reserve the chain gets, and what is kept.
#include "relslam/plane/rlt_xpoint_ref.hpp"

#include <gtest/gtest.h>

namespace relslam::plane {
namespace {

constexpr double kSameLength = 0.02;  // τ_len, the options' default
constexpr PlaneId kPartner = 3;

// A comparison that places both planes: the child (second side) at `length` over `samples`
// iterations, the partner (first side) at `partner_length` anchored on `partner_key_point`.
CompareResult comparison(double length, int samples, double partner_length, KeyPoint partner_key_point,
                         double offset) {
  CompareResult r;
  r.valid = true;
  r.delta = {Eigen::Vector2d(offset, 1.0), 0.25};
  r.length1 = partner_length;
  r.length2 = length;
  r.key_point1 = partner_key_point;
  r.key_point2 = KeyPoint::Left;
  r.samples = samples;
  r.interval = {100, 100 + samples - 1};
  return r;
}

RltXPointRef with_reserve(const CompareResult& reserve) {
  RltXPointRef ref;
  CompareResult first = reserve;
  EXPECT_FALSE(do_backup_check(ref, kPartner, first, kSameLength));  // the first result becomes the reserve
  EXPECT_TRUE(ref.reserve.has_value());
  return ref;
}

TEST(RltXPointRefBackup, BiggerReserveIsRestoredWithThePartnersSizeAndKeyPointOfItsTime) {
  RltXPointRef ref = with_reserve(comparison(4.0, 30, 3.0, KeyPoint::Left, 2.0));
  CompareResult current = comparison(2.5, 80, 5.0, KeyPoint::Right, 7.0);
  EXPECT_TRUE(do_backup_check(ref, kPartner, current, kSameLength));
  EXPECT_EQ(current.length2, 4.0);
  EXPECT_EQ(current.samples, 30);
  EXPECT_EQ(current.delta.translation.x(), 2.0);
  // The partner as the reserve saw it, for Rule 28's re-anchoring, not as it is now.
  EXPECT_EQ(current.length1, 3.0);
  EXPECT_EQ(current.key_point1, KeyPoint::Left);
  EXPECT_EQ(ref.reserve->length2, 4.0);  // the reserve stays
}

TEST(RltXPointRefBackup, AboutEqualSizesKeepTheLongerInterval) {
  RltXPointRef ref = with_reserve(comparison(4.0, 30, 3.0, KeyPoint::Left, 2.0));
  CompareResult shorter = comparison(4.0 + kSameLength / 2, 20, 3.0, KeyPoint::Left, 9.0);
  EXPECT_TRUE(do_backup_check(ref, kPartner, shorter, kSameLength));  // within τ_len: 30 iterations win
  EXPECT_EQ(shorter.samples, 30);
  EXPECT_EQ(shorter.delta.translation.x(), 2.0);

  CompareResult longer = comparison(4.0 - kSameLength / 2, 40, 3.0, KeyPoint::Left, 9.0);
  EXPECT_FALSE(do_backup_check(ref, kPartner, longer, kSameLength));  // 40 iterations replace it
  EXPECT_EQ(longer.delta.translation.x(), 9.0);
  EXPECT_EQ(ref.reserve->samples, 40);
}

TEST(RltXPointRefBackup, SmallerReserveIsOverwritten) {
  RltXPointRef ref = with_reserve(comparison(2.0, 90, 3.0, KeyPoint::Left, 2.0));
  CompareResult current = comparison(4.0, 10, 5.0, KeyPoint::Right, 7.0);
  EXPECT_FALSE(do_backup_check(ref, kPartner, current, kSameLength));
  EXPECT_EQ(current.length2, 4.0);
  EXPECT_EQ(ref.reserve->length2, 4.0);
  EXPECT_EQ(ref.reserve->length1, 5.0);
  EXPECT_EQ(ref.reserve->key_point1, KeyPoint::Right);
}

// The circular array overwrote the pair's shared iterations: no comparison, the reserve stands
// in; an unplaceable result (Rule 15's tie) is never kept.
TEST(RltXPointRefBackup, ReserveStandsInWhenNoComparisonCanBeMade) {
  RltXPointRef ref = with_reserve(comparison(2.0, 90, 3.0, KeyPoint::Left, 2.0));
  CompareResult none;
  EXPECT_TRUE(do_backup_check(ref, kPartner, none, kSameLength));
  EXPECT_TRUE(none.valid);
  EXPECT_EQ(none.length2, 2.0);

  CompareResult tie = comparison(6.0, 90, 3.0, KeyPoint::Left, 5.0);
  tie.ambiguous = true;
  EXPECT_TRUE(do_backup_check(ref, kPartner, tie, kSameLength));
  EXPECT_EQ(ref.reserve->length2, 2.0);
}

// A reserve belongs to its pair: another chain parent (Rule 30) starts afresh.
TEST(RltXPointRefBackup, AnotherPartnerDropsTheReserve) {
  RltXPointRef ref = with_reserve(comparison(4.0, 30, 3.0, KeyPoint::Left, 2.0));
  CompareResult other = comparison(2.0, 10, 5.0, KeyPoint::Right, 7.0);
  EXPECT_FALSE(do_backup_check(ref, kPartner + 1, other, kSameLength));
  EXPECT_EQ(other.length2, 2.0);
  EXPECT_EQ(ref.reserve_partner, kPartner + 1);
  EXPECT_EQ(ref.reserve->length2, 2.0);
}

// The test Rule 35's snapshot shares (thesis 4.3.7.3).
TEST(RltXPointRefBackup, ReplacesSavedOrdersBySizeThenInterval) {
  EXPECT_TRUE(replaces_saved(5.0, 1, 4.0, 100, kSameLength));
  EXPECT_FALSE(replaces_saved(3.0, 100, 4.0, 1, kSameLength));
  EXPECT_TRUE(replaces_saved(4.01, 50, 4.0, 50, kSameLength));
  EXPECT_FALSE(replaces_saved(4.01, 49, 4.0, 50, kSameLength));
}

}  // namespace
}  // namespace relslam::plane
