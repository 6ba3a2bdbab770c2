#include "relslam/plane/rlt_xpoint.hpp"

#include "plane_world_fixture.hpp"
#include "seeded_random.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <vector>

namespace relslam::plane {
namespace {

constexpr double kPi = std::numbers::pi;
// E31: chain orders agree to 1e-9 without noise or with position-only noise.
constexpr double kSameMap = 1e-9;

// RltPlanes of the four planes world over one loop, every wall seen in every iteration; with
// `position_noise` each observation is shifted (not turned) by a random offset.
std::vector<RltPlane> four_planes(double position_noise) {
  const std::vector<test::Wall> walls = test::four_planes_walls();
  const test::PlaneRun run = test::run_path(walls, test::four_planes_path(1, 0.2, 5 * kPi / 180), {.always = true});
  relslam::test::SeededRandom random(5);
  std::vector<RltPlane> planes;
  for (const PlaneFrame& frame : run.frames)
    for (int w = 0; w < 4; ++w) {
      PlaneObject seen = frame.planes[w];
      const Eigen::Vector2d shift(position_noise * random.gaussian(), position_noise * random.gaussian());
      seen.a += shift;
      seen.b += shift;
      if (frame.iteration == 0)
        planes.emplace_back(w, seen, 2000);
      else
        planes[w].add(seen);
    }
  return planes;
}

// Each plane's pose relative to every other: what a map built from the group keeps whatever
// the group frame (the base plane) is.
double largest_difference(const std::vector<RltPlane>& a, XPointId xa, const std::vector<RltPlane>& b, XPointId xb) {
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < a.size(); ++j) {
      const PlanarPose in_a = a[i].ref(xa)->pose.inverse() * a[j].ref(xa)->pose;
      const PlanarPose in_b = b[i].ref(xb)->pose.inverse() * b[j].ref(xb)->pose;
      worst = std::max(
          {worst, (in_a.translation - in_b.translation).norm(), std::abs(wrap_angle(in_a.heading - in_b.heading))});
    }
  return worst;
}

void expect_chain_order_independent(double position_noise) {
  const std::vector<std::vector<PlaneId>> orders = {{0, 1, 2, 3}, {3, 1, 0, 2}, {2, 0, 3, 1}, {1, 3, 2, 0}};
  std::vector<RltPlane> reference = four_planes(position_noise);
  RltXPoint first(0, 0, orders[0]);
  for (PlaneId p : orders[0]) reference[p].join(0, 0);
  first.compute(reference, {});
  for (const std::vector<PlaneId>& order : orders) {
    std::vector<RltPlane> planes = four_planes(position_noise);
    RltXPoint group(0, 0, {0, 1, 2, 3});
    for (PlaneId p : order) planes[p].join(0, 0);
    group.set_chain(order);
    group.compute(planes, {});
    for (const RltPlane& p : planes) ASSERT_TRUE(p.ref(0)->valid);
    EXPECT_LT(largest_difference(reference, 0, planes, 0), kSameMap)
        << "order " << order[0] << order[1] << order[2] << order[3];
  }
}

TEST(RltXPoint, Rule2ChainOrderDoesNotChangeANoiseFreeMap) { expect_chain_order_independent(0.0); }

TEST(RltXPoint, Rule2ChainOrderDoesNotChangeTheMapUnderPositionOnlyNoise) { expect_chain_order_independent(0.05); }

TEST(RltXPoint, ComputePlacesEveryPlaneWhereTheWallsAre) {
  std::vector<RltPlane> planes = four_planes(0.0);
  RltXPoint group(0, 0, {0, 1, 2, 3});
  for (PlaneId p = 0; p < 4; ++p) planes[p].join(0, 0);
  group.compute(planes, {});
  const std::vector<test::Wall> walls = test::four_planes_walls();
  const PlanarPose world_T_base = PlaneObject{walls[0].a, walls[0].b}.pose();
  for (PlaneId p = 0; p < 4; ++p) {
    const PlanarPose expected = PlaneObject{walls[p].a, walls[p].b}.pose();
    const PlanarPose found = world_T_base * planes[p].ref(0)->pose;
    EXPECT_LT((found.translation - expected.translation).norm(), 1e-12) << "plane " << p;
    EXPECT_NEAR(planes[p].ref(0)->max_length, 8, 1e-12);
  }
  EXPECT_FALSE(group.needs_compute());
}

TEST(RltXPoint, Rule7JoinsOnlyAPlaneSeenWithEveryMember) {
  // Planes 0 and 1 seen in 0–9; plane 2 in 5–14 (shares 5 with both); plane 3 in 12–20.
  const auto plane = [](PlaneId id, int from, int to) {
    RltPlane p(id, PlaneObject{{0, 0}, {1, 0}, 0.0, 2.5, from}, 100);
    for (int t = from + 1; t <= to; ++t) p.add(PlaneObject{{0, 0}, {1, 0}, 0.0, 2.5, t});
    return p;
  };
  std::vector<RltPlane> planes = {plane(0, 0, 9), plane(1, 0, 9), plane(2, 5, 14), plane(3, 12, 20)};
  RltXPoint group(0, 0, {0, 1});
  planes[0].join(0, 0);
  planes[1].join(0, 0);
  EXPECT_TRUE(group.can_add(planes, planes[2], 5));
  EXPECT_FALSE(group.can_add(planes, planes[2], 6));
  group.add_plane(planes, 2, 14);
  EXPECT_FALSE(group.can_add(planes, planes[3], 1));  // never seen with planes 0 and 1
  EXPECT_THROW(group.set_chain({0, 1, 3}), std::logic_error);
}

// Rule 37 (thesis 4.3.6): a one-way link is for charting only. The group does not list the plane,
// the plane has no membership in it, and the group computes exactly what it computes without the
// link (every field of every reference and edge bit for bit).
TEST(RltXPoint, Rule37OneWayLinkNeitherJoinsTheGroupNorChangesItsComputation) {
  RelativePlaneOptions options;
  options.key_points = true;
  const auto group_of_three = [&](std::vector<RltPlane>& planes) {
    RltXPoint group(0, 0, {0, 1, 2});
    for (PlaneId p = 0; p < 3; ++p) planes[p].join(0, 0);
    return group;
  };
  std::vector<RltPlane> plain = four_planes(0.05), linked = four_planes(0.05);
  RltXPoint without = group_of_three(plain), with = group_of_three(linked);
  EXPECT_TRUE(linked[3].add_oneway(0));
  EXPECT_FALSE(linked[3].add_oneway(0));  // once
  EXPECT_FALSE(linked[1].add_oneway(0));  // a member has its two-way membership
  without.compute(plain, options);
  with.compute(linked, options);
  EXPECT_EQ(with.planes(), (std::vector<PlaneId>{0, 1, 2}));
  EXPECT_EQ(linked[3].ref(0), nullptr);
  EXPECT_EQ(linked[3].oneway_xpoints(), (std::vector<XPointId>{0}));
  for (PlaneId p = 0; p < 3; ++p) {
    const RltXPointRef &a = *plain[p].ref(0), &b = *linked[p].ref(0);
    EXPECT_TRUE(a.valid && b.valid) << "plane " << p;
    EXPECT_EQ(a.pose.translation, b.pose.translation) << "plane " << p;
    EXPECT_EQ(a.pose.heading, b.pose.heading) << "plane " << p;
    EXPECT_EQ(a.max_length, b.max_length) << "plane " << p;
    EXPECT_EQ(a.key_point, b.key_point) << "plane " << p;
    EXPECT_EQ(a.samples, b.samples) << "plane " << p;
  }
  ASSERT_EQ(without.edges().size(), with.edges().size());
  for (std::size_t e = 0; e < with.edges().size(); ++e) {
    EXPECT_EQ(without.edges()[e].delta.translation, with.edges()[e].delta.translation) << "edge " << e;
    EXPECT_EQ(without.edges()[e].delta.heading, with.edges()[e].delta.heading) << "edge " << e;
    EXPECT_EQ(without.edges()[e].samples, with.edges()[e].samples) << "edge " << e;
  }
}

}  // namespace
}  // namespace relslam::plane
