#include "relslam/sim/point_sensor.hpp"
#include "relslam/sim/planar_simulator.hpp"

#include "described_fields.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace relslam::sim {
namespace {

// Field points are a + s·u on a wall of coordinates ~10: a few ulps.
constexpr double kOnWall = 1e-12;

PlanarWorld world_of(std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> segments) {
  PlanarWorld world;
  for (std::size_t i = 0; i < segments.size(); ++i)
    world.walls.push_back(Wall::between(static_cast<int>(i) + 10, segments[i].first, segments[i].second));
  return world;
}

PointSensorOptions exact() {
  PointSensorOptions o;
  o.sigma = 0.0;
  o.shuffle = false;
  return o;
}

// The robot at the world origin facing +x: robot and world frames coincide.
PointSimFrame look(const PointSensorOptions& o, const PlanarWorld& world, int k = 0, std::uint64_t seed = 1) {
  return PointSensor(o, world, seed).observe(PlanarPose::identity(), k);
}

int count_of(const PointSimFrame& f, int wall_id) {
  return static_cast<int>(std::count(f.truth.wall_ids.begin(), f.truth.wall_ids.end(), wall_id));
}

TEST(PointSensor, DefaultsAreValid) {
  const PointSensorOptions o;
  EXPECT_TRUE(check(o).empty());
  EXPECT_EQ(o.spacing, 0.2);
  EXPECT_EQ(o.jitter, 0.25);
  EXPECT_EQ(o.sigma, 0.05);
  EXPECT_TRUE(o.backface_cull);
  EXPECT_TRUE(o.occlusion);
}

TEST(PointSensor, EveryFieldButTheFrustumHasAScenarioKey) {
  // The frustum is set from a preset (the map's), not field by field.
  EXPECT_EQ(relslam::test::described_count<PointSensorOptions>() + 1,
            relslam::test::member_count<PointSensorOptions>());
}

TEST(PointSensor, CheckNamesFrustumAndFieldProblems) {
  PointSensorOptions o;
  o.frustum.far = 0;
  o.spacing = 0;
  o.jitter = 0.6;
  o.sigma = std::nan("");
  const std::vector<OptionIssue> issues = check(o);
  ASSERT_EQ(issues.size(), 4u);
  EXPECT_EQ(issues[0].field, "frustum.far");
  EXPECT_EQ(issues[1].field, "spacing");
  EXPECT_EQ(issues[1].problem, "must be > 0, got 0");
  EXPECT_EQ(issues[2].field, "jitter");
  EXPECT_EQ(issues[3].field, "sigma");
  EXPECT_THROW(PointSensor(o, world_of({{{5, -1}, {5, 1}}}), 1), OptionError);
}

TEST(PointSensor, MatchingTakesThePlaneSensorsFrustumAndCulling) {
  PlaneSensorOptions plane;
  plane.frustum = ViewingFrustum::large();
  plane.backface_cull = false;
  const PointSensorOptions o = PointSensorOptions::matching(plane);
  EXPECT_EQ(o.frustum.far, 30.0);
  EXPECT_FALSE(o.backface_cull);
  EXPECT_EQ(o.sigma, PointSensorOptions{}.sigma);
}

TEST(PointSensor, FieldIsAJitteredGridInsideEachWallsCells) {
  // 4 long and 2.5 high at spacing 0.2: 20 × 13 cells (the height's cells are 2.5/13 high).
  const PlanarWorld world = world_of({{{1, 2}, {1 + 4 * 0.6, 2 + 4 * 0.8}}});
  const PointField field = make_point_field(world, 0.2, 0.25, 7);
  ASSERT_EQ(field.points.size(), 20u * 13u);
  ASSERT_EQ(field.first_point, (std::vector<std::size_t>{0, 260}));
  const Wall& wall = world.walls[0];
  const double cell_s = 0.2, cell_y = 2.5 / 13;
  double largest_shift = 0;
  for (std::size_t n = 0; n < field.points.size(); ++n) {
    const Eigen::Vector3d& p = field.points[n].p_world;
    const Eigen::Vector2d xz(p.x(), p.z());
    EXPECT_NEAR(wall.normal().dot(xz - wall.a), 0.0, kOnWall) << "point " << n;
    const int i = static_cast<int>(n) / 13, j = static_cast<int>(n) % 13;
    const double s = wall.tangent().dot(xz - wall.a);
    EXPECT_LE(std::abs(s - (i + 0.5) * cell_s), 0.25 * cell_s + kOnWall) << "point " << n;
    EXPECT_LE(std::abs(p.y() - (j + 0.5) * cell_y), 0.25 * cell_y + kOnWall) << "point " << n;
    largest_shift = std::max(largest_shift, std::abs(s - (i + 0.5) * cell_s));
  }
  EXPECT_GT(largest_shift, 0.2 * cell_s) << "the jitter is used";
  // The seed fixes the field, bit for bit; another seed moves it.
  const PointField again = make_point_field(world, 0.2, 0.25, 7), other = make_point_field(world, 0.2, 0.25, 8);
  for (std::size_t n = 0; n < field.points.size(); ++n) EXPECT_EQ(field.points[n].p_world, again.points[n].p_world);
  EXPECT_NE(field.points[0].p_world, other.points[0].p_world);
  // No jitter: the cell centres.
  EXPECT_NEAR(make_point_field(world, 0.2, 0.0, 7).points[0].p_world.y(), 0.5 * cell_y, kOnWall);
}

TEST(PointSensor, TooFineASpacingIsRefusedBeforeAllocating) {
  PointSensorOptions o = exact();
  o.spacing = 1e-4;
  EXPECT_THROW(PointSensor(o, world_of({{{5, -100}, {5, 100}}}), 1), OptionError);
}

TEST(PointSensor, BackFacingWallGivesNoPoints) {
  // The same segment both ways round: front towards the robot (normal −x), then away from it.
  const PlanarWorld facing = world_of({{{5, -1}, {5, 1}}}), away = world_of({{{5, 1}, {5, -1}}});
  EXPECT_GT(look(exact(), facing).observation.points.size(), 100u);
  EXPECT_TRUE(look(exact(), away).observation.points.empty());
  PointSensorOptions both_sides = exact();
  both_sides.backface_cull = false;
  EXPECT_EQ(look(both_sides, away).observation.points.size(), look(exact(), facing).observation.points.size());
}

TEST(PointSensor, PointsBehindAnotherWallAreHidden) {
  // A short wall at x = 3 (|z| <= 0.5) in front of a long one at x = 6: the rays to points of
  // the far wall with |z| < 1 pass through the near wall (similar triangles, 0.5 · 6/3).
  const PlanarWorld world = world_of({{{3, -0.5}, {3, 0.5}}, {{6, -3}, {6, 3}}});
  const PointSimFrame f = look(exact(), world);
  ASSERT_EQ(f.observation.points.size(), f.truth.wall_ids.size());
  int far_seen = 0;
  for (std::size_t i = 0; i < f.observation.points.size(); ++i) {
    if (f.truth.wall_ids[i] != 11) continue;
    ++far_seen;
    EXPECT_GE(std::abs(f.observation.points[i].z()), 1.0) << "point " << i << " is behind the near wall";
  }
  EXPECT_GT(far_seen, 50);
  EXPECT_GT(count_of(f, 10), 50) << "the occluding wall itself is seen";
  // Without occlusion the hidden points come back.
  PointSensorOptions see_through = exact();
  see_through.occlusion = false;
  const PointSimFrame all = look(see_through, world);
  EXPECT_GT(count_of(all, 11), far_seen + 50);
  // A wall behind the robot's back cannot hide anything in front of it.
  const PlanarWorld behind = world_of({{{-3, 0.5}, {-3, -0.5}}, {{6, -3}, {6, 3}}});
  EXPECT_EQ(count_of(look(exact(), behind), 11), count_of(all, 11));
}

TEST(PointSensor, OnlyPointsInsideTheFrustumAreReported) {
  // A wall across the view at x = 5, wider than the footprint (|z| <= 5·tan 30° ≈ 2.89), and one
  // beyond the far end (x = 8 > 7).
  const PlanarWorld world = world_of({{{5, -6}, {5, 6}}, {{8, -1}, {8, 1}}});
  const PointSensorOptions o = exact();
  const PointSimFrame f = look(o, world);
  const PointField field = make_point_field(world, o.spacing, o.jitter, 1);
  int inside = 0;
  for (std::size_t i = field.first_point[0]; i < field.first_point[1]; ++i) {
    const Eigen::Vector3d& p = field.points[i].p_world;
    inside += o.frustum.contains({p.x(), p.z()});
  }
  EXPECT_EQ(count_of(f, 10), inside);
  EXPECT_LT(inside, static_cast<int>(field.first_point[1]));
  EXPECT_EQ(count_of(f, 11), 0) << "beyond the far end";
  const double z_max = 5 * std::tan(30.0 * std::numbers::pi / 180.0);
  for (const Eigen::Vector3d& p : f.observation.points) EXPECT_LE(std::abs(p.z()), z_max + kOnWall);
}

TEST(PointSensor, NoiseFreePointsLieExactlyOnTheirWallsInTheRobotFrame) {
  // A room seen from an oblique pose: every reported point, mapped back to the world, is on its
  // wall (inside its extent and height).
  const PlanarWorld world = world_of({{{0, 0}, {8, 0}}, {{8, 0}, {8, 6}}, {{8, 6}, {0, 6}}, {{0, 6}, {0, 0}},
                                      {{3, 2.5}, {3, 3.5}}});
  const PlanarPose world_T_robot = PlanarPose::from(1.5, 1.0, 0.4);
  const PointSimFrame f = PointSensor(exact(), world, 3).observe(world_T_robot, 5);
  ASSERT_GT(f.observation.points.size(), 200u);
  EXPECT_EQ(f.observation.iteration, 5);
  EXPECT_EQ(f.truth.world_T_robot.heading, world_T_robot.heading);
  for (std::size_t i = 0; i < f.observation.points.size(); ++i) {
    const Eigen::Vector3d& p = f.observation.points[i];
    const Eigen::Vector2d xz = world_T_robot * Eigen::Vector2d(p.x(), p.z());
    const Wall& wall = world.walls[static_cast<std::size_t>(f.truth.wall_ids[i] - 10)];
    EXPECT_NEAR(wall.normal().dot(xz - wall.a), 0.0, kOnWall) << "point " << i;
    const double s = wall.tangent().dot(xz - wall.a);
    EXPECT_GT(s, 0.0);
    EXPECT_LT(s, wall.length());
    EXPECT_GT(p.y(), 0.0);
    EXPECT_LT(p.y(), wall.height);
  }
}

TEST(PointSensor, NoiseIsFreshPerIterationAndHasTheRequestedSpread) {
  const PlanarWorld world = world_of({{{5, -2.5}, {5, 2.5}}});
  PointSensorOptions o = exact();
  o.sigma = 0.05;
  const PointSensor sensor(o, world, 11);
  const PointSimFrame a = sensor.observe(PlanarPose::identity(), 0), b = sensor.observe(PlanarPose::identity(), 1);
  ASSERT_EQ(a.observation.points.size(), b.observation.points.size()) << "visibility is judged on the true points";
  double sum = 0, sum2 = 0;
  for (const Eigen::Vector3d& p : a.observation.points) {
    sum += p.x() - 5.0;
    sum2 += (p.x() - 5.0) * (p.x() - 5.0);
  }
  const double n = static_cast<double>(a.observation.points.size());
  // About 440 samples: the mean within ~4 standard errors, σ within 15 %.
  EXPECT_NEAR(sum / n, 0.0, 4 * 0.05 / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(sum2 / n), 0.05, 0.15 * 0.05);
  EXPECT_NE(a.observation.points[0], b.observation.points[0]) << "noise is redrawn each iteration";
}

TEST(PointSensor, SameSeedGivesTheSameBitsAndShufflingOnlyReorders) {
  const PlanarWorld world = world_of({{{5, -2}, {5, 2}}, {{6, 2.5}, {3, 2.5}}});
  const PointSensorOptions o;  // noise and shuffle on
  const PointSimFrame x = look(o, world, 4, 21), y = look(o, world, 4, 21), other = look(o, world, 4, 22);
  ASSERT_EQ(x.observation.points.size(), y.observation.points.size());
  for (std::size_t i = 0; i < x.observation.points.size(); ++i) {
    EXPECT_EQ(x.observation.points[i], y.observation.points[i]);
    EXPECT_EQ(x.truth.wall_ids[i], y.truth.wall_ids[i]);
  }
  EXPECT_NE(x.observation.points[0], other.observation.points[0]);
  PointSensorOptions ordered = o;
  ordered.shuffle = false;
  const PointSimFrame z = look(ordered, world, 4, 21);
  ASSERT_EQ(z.observation.points.size(), x.observation.points.size());
  EXPECT_TRUE(std::is_sorted(z.truth.wall_ids.begin(), z.truth.wall_ids.end())) << "field order without shuffle";
  EXPECT_FALSE(std::is_sorted(x.truth.wall_ids.begin(), x.truth.wall_ids.end()));
  auto key = [](const Eigen::Vector3d& p) { return std::tuple(p.x(), p.y(), p.z()); };
  std::vector<std::tuple<double, double, double>> xs, zs;
  for (const Eigen::Vector3d& p : x.observation.points) xs.push_back(key(p));
  for (const Eigen::Vector3d& p : z.observation.points) zs.push_back(key(p));
  std::sort(xs.begin(), xs.end());
  std::sort(zs.begin(), zs.end());
  EXPECT_EQ(xs, zs) << "the same points (each point's noise is its own), reordered";
}

TEST(SegmentCrossesWall, OnlyAProperCrossingBlocks) {
  const Wall wall = Wall::between(0, {2, -1}, {2, 1});
  EXPECT_TRUE(segment_crosses_wall({4, 0}, {0, 0}, wall));
  EXPECT_FALSE(segment_crosses_wall({4, 3}, {0, 0}, wall)) << "passes beside the end";
  EXPECT_FALSE(segment_crosses_wall({2, 0.5}, {0, 0}, wall)) << "starts on the wall: the point's own wall";
  EXPECT_FALSE(segment_crosses_wall({1.5, 0}, {0, 0}, wall)) << "stops short";
  EXPECT_FALSE(segment_crosses_wall({2, 3}, {2, 5}, wall)) << "on the wall's line, beyond it";
}

TEST(PlanarSimulator, PointFramesNeedThePointSensorAndLeavePlaneFramesAlone) {
  PlanarMap map;
  map.world = world_of({{{5, -2}, {5, 2}}, {{-5, 2}, {-5, -2}}});
  map.path.steps.push_back(PathOperation::turn(std::numbers::pi));
  const PlanarSimulator planes(map, 3);
  EXPECT_FALSE(planes.has_point_sensor());
  EXPECT_THROW(planes.point_frame(0), std::logic_error);
  const PlanarSimulator both(map, 3, PointSensorOptions::matching(map.sensor));
  ASSERT_TRUE(both.has_point_sensor());
  const PlaneSimFrame plane_frame = both.frame(0), plane_only = planes.frame(0);
  ASSERT_EQ(plane_frame.observation.planes.size(), plane_only.observation.planes.size());
  EXPECT_EQ(plane_frame.observation.planes[0].a, plane_only.observation.planes[0].a);
  const PointSimFrame start = both.point_frame(0), end = both.point_frame(both.iterations() - 1);
  EXPECT_GT(count_of(start, 10), 0);
  EXPECT_EQ(count_of(start, 11), 0);
  EXPECT_EQ(count_of(end, 10), 0) << "turned round";
  EXPECT_GT(count_of(end, 11), 0);
}

}  // namespace
}  // namespace relslam::sim
