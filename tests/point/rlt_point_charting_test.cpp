#include "relslam/point/rlt_point_charting.hpp"

#include "seeded_random.hpp"

#include <gtest/gtest.h>

#include <set>

namespace relslam::point {
namespace {

TEST(RltPointCharting, EnumerationIsDuplicateFreeAndComplete) {
  test::SeededRandom rng(401);
  RltPointCharting charting(64);
  std::vector<std::set<int>> truth(200);
  for (int k = 0; k < 200; ++k) {
    charting.begin_iteration(k);
    std::set<int> ids;
    while (ids.size() < 30) ids.insert(static_cast<int>(rng.below(100)));
    for (int id : ids) charting.add(id);
    truth[k] = ids;
  }
  for (int a = 140; a < 200; a += 9) {  // the window keeps iterations 136..199
    const int b = std::min(199, a + 15);
    std::vector<PointId> out;
    charting.enumerate_unique(a, b, out);
    std::set<int> expected;
    for (int k = a; k <= b; ++k) expected.insert(truth[k].begin(), truth[k].end());
    EXPECT_EQ(std::set<int>(out.begin(), out.end()), expected);
    EXPECT_EQ(out.size(), expected.size()) << "no duplicates";
  }
}

TEST(RltPointCharting, ForgetsIterationsOutsideItsWindowAndClearsSkippedOnes) {
  RltPointCharting charting(4);
  for (int k = 0; k < 6; ++k) {
    charting.begin_iteration(k);
    charting.add(k);
  }
  EXPECT_TRUE(charting.at(1).empty()) << "outside the window";
  EXPECT_EQ(charting.at(5), std::vector<PointId>{5});
  charting.begin_iteration(8);  // 6 and 7 had no frame
  EXPECT_TRUE(charting.at(7).empty());
  EXPECT_TRUE(charting.at(6).empty());
  std::vector<PointId> out;
  charting.enumerate_unique(0, 8, out);
  EXPECT_EQ(out, std::vector<PointId>{5});
  EXPECT_THROW(charting.begin_iteration(8), std::logic_error);
}

TEST(RltPointCharting, ReplaceRedirectsWithoutDuplicates) {
  RltPointCharting charting(8);
  charting.begin_iteration(0);
  charting.add(1);
  charting.add(2);
  charting.begin_iteration(1);
  charting.add(2);
  charting.replace(2, 1);
  EXPECT_EQ(charting.at(0), std::vector<PointId>{1});
  EXPECT_EQ(charting.at(1), std::vector<PointId>{1});
}

// Windows that end at the newest iteration come from the recency list, the others from the
// slots: both must list what the slots hold, merges (replace) included.
TEST(RltPointCharting, WindowsEndingNowMatchTheSlotsAfterMerges) {
  test::SeededRandom rng(402);
  RltPointCharting charting(64);
  int next_id = 0;
  std::vector<int> alive;
  for (int k = 0; k < 300; ++k) {
    charting.begin_iteration(k == 150 ? 160 : k < 150 ? k : k + 10);  // one gap of skipped iterations
    for (int n = 0; n < 3; ++n) alive.push_back(next_id++);
    std::set<int> seen;
    for (int id : alive)
      if (rng.below(4) != 0) seen.insert(id);
    for (int id : seen) charting.add(id);
    if (alive.size() > 40) alive.erase(alive.begin(), alive.begin() + 3);
    if (k % 7 == 6 && alive.size() > 2) {  // a newer point merged into an older one
      const int newer = alive.back(), older = alive.front();
      charting.replace(newer, older);
      alive.pop_back();
    }
    const int now = charting.newest();
    for (int back : {0, 1, 5, 30, 63, 80}) {
      std::set<int> expected;
      for (int t = now - back; t <= now; ++t) expected.insert(charting.at(t).begin(), charting.at(t).end());
      std::vector<PointId> out;
      charting.enumerate_unique(now - back, now, out);
      EXPECT_EQ(std::set<int>(out.begin(), out.end()), expected) << "iteration " << now << " back " << back;
      EXPECT_EQ(out.size(), expected.size()) << "iteration " << now << " back " << back << ": no duplicates";
    }
  }
}

}  // namespace
}  // namespace relslam::point
