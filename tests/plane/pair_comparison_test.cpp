#include "relslam/plane/pair_comparison.hpp"

#include "clipped_wall_fixture.hpp"
#include "relslam/plane/key_point_compare.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace relslam::plane {
namespace {

using test::ClippedWall;

// A wall across the view, seen whole, out of view 5 iterations in every 97.
ClippedWall across() {
  return {{4, -5}, {4, 3}, test::constant(0), [](int t) { return t % 97 < 5 ? 0.0 : 8.0; }};
}

// A wall that grows and shrinks at both ends, out of sync, out of view 4 iterations in every 61:
// many growth phases (Rule 18) in every run of common iterations.
ClippedWall breathing() {
  return {{-1, -6},
          {7, -6},
          [](int t) { return t % 61 >= 57 ? 8.0 : std::max(0.0, 3 * std::sin(t * 0.07)); },
          [](int t) { return std::min(8.0, 5 + 3 * std::cos(t * 0.05)); }};
}

void expect_same(const CompareResult& kept, const CompareResult& whole, int t) {
  SCOPED_TRACE("iteration " + std::to_string(t));
  ASSERT_EQ(kept.valid, whole.valid);
  EXPECT_EQ(kept.interval.start, whole.interval.start);
  EXPECT_EQ(kept.interval.end, whole.interval.end);
  EXPECT_EQ(kept.samples, whole.samples);
  EXPECT_EQ(kept.delta.translation, whole.delta.translation);
  EXPECT_EQ(kept.delta.heading, whole.delta.heading);
  EXPECT_EQ(kept.length1, whole.length1);
  EXPECT_EQ(kept.length2, whole.length2);
  EXPECT_EQ(kept.key_point1, whole.key_point1);
  EXPECT_EQ(kept.key_point2, whole.key_point2);
  EXPECT_EQ(kept.static1, whole.static1);
  EXPECT_EQ(kept.static2, whole.static2);
  EXPECT_EQ(kept.ambiguous, whole.ambiguous);
  EXPECT_EQ(kept.sigma, whole.sigma);
}

// The incremental edge comparison is an optimisation only: at every iteration its result is
// bit for bit the comparison over both planes' whole stored histories — across gaps (closed
// runs), while the circular arrays overwrite the oldest runs (capacity 150 of 600 iterations),
// and when the edge's planes change (the chain reordered: the pair is taken the other way round).
TEST(PairComparison, GivesTheWholeHistoryComparisonAtEveryIterationThroughGapsAndWrapAround) {
  relslam::test::SeededRandom random(7);
  const test::ClipNoise noise{0.01, 0.002, 0.01};
  const int n = 600;
  const std::vector<PlaneObject> seen1 = test::observe_clipped(across(), 0, n, noise, random);
  const std::vector<PlaneObject> seen2 = test::observe_clipped(breathing(), 0, n, noise, random);
  const RelativePlaneOptions options;
  std::optional<RltPlane> a, b;
  std::size_t i = 0, j = 0;
  PairComparison pair;
  CompareResult kept;
  int recomputed = 0, unchanged = 0;
  for (int t = 0; t < n; ++t) {
    const auto store = [t](std::optional<RltPlane>& plane, PlaneId id, const std::vector<PlaneObject>& seen,
                           std::size_t& next) {
      if (next == seen.size() || seen[next].iteration != t) return;
      if (plane)
        plane->add(seen[next++]);
      else
        plane.emplace(id, seen[next++], 150);
    };
    store(a, 0, seen1, i);
    store(b, 1, seen2, j);
    if (!a || !b) continue;
    const bool swapped = t >= 400;
    const RltPlane& first = swapped ? *b : *a;
    const RltPlane& second = swapped ? *a : *b;
    if (const CompareResult* r = pair.update(first, second, options)) {
      kept = *r;
      ++recomputed;
    } else {
      ++unchanged;
    }
    expect_same(kept, compare_with_key_points(first.view(), second.view(), options), t);
    if (testing::Test::HasFatalFailure()) return;
  }
  EXPECT_GT(recomputed, 300);
  EXPECT_GT(unchanged, 10);  // iterations in which only one plane was seen
  EXPECT_TRUE(kept.valid);
  EXPECT_EQ(a->size(), 150);  // the arrays wrapped
  EXPECT_GT(a->readings(), 400);
}

}  // namespace
}  // namespace relslam::plane
