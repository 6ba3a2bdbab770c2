// The ray-cast range sensors of the planar world: the 2-D laser and the depth camera, exact on a
// noise-free square room against analytic ranges and depths, seeded noise reproducible.
#include "relslam/sim/depth_camera.hpp"
#include "relslam/sim/laser_sensor.hpp"
#include "relslam/sim/ray_cast.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace relslam::sim {
namespace {

// The square [-h, h]² seen from inside (fronts facing in), walls of height 2.5, ids 10..13:
// 10 at z = -h, 11 at x = +h, 12 at z = +h, 13 at x = -h.
PlanarWorld square_room(double h) {
  PlanarWorld w;
  w.walls = {Wall::between(10, {-h, -h}, {h, -h}), Wall::between(11, {h, -h}, {h, h}),
             Wall::between(12, {h, h}, {-h, h}), Wall::between(13, {-h, h}, {-h, -h})};
  return w;
}

// Distance from p along heading `angle` to the square's boundary |x|, |z| <= h.
double square_range(const Eigen::Vector2d& p, double angle, double h) {
  const double c = std::cos(angle), s = std::sin(angle);
  double best = 1e300;
  if (c > 1e-12) best = std::min(best, (h - p.x()) / c);
  if (c < -1e-12) best = std::min(best, (-h - p.x()) / c);
  if (s > 1e-12) best = std::min(best, (h - p.y()) / s);
  if (s < -1e-12) best = std::min(best, (-h - p.y()) / s);
  return best;
}

TEST(RayCast, HitsSortedAndBothSides) {
  const PlanarWorld room = square_room(2.0);
  const std::vector<RayHit> hits = ray_hits(room, {-3.0, 0.5}, {1.0, 0.0}, 100.0);  // from outside, through both
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_DOUBLE_EQ(hits[0].distance, 1.0);
  EXPECT_EQ(hits[0].wall, 3);  // the back of wall 13
  EXPECT_DOUBLE_EQ(hits[1].distance, 5.0);
  EXPECT_EQ(first_ray_hit(room, {-3.0, 0.5}, {1.0, 0.0}, 100.0)->wall, 3);
  EXPECT_TRUE(ray_hits(room, {-3.0, 0.5}, {1.0, 0.0}, 0.5).empty());
  EXPECT_FALSE(first_ray_hit(room, {-3.0, 0.5}, {-1.0, 0.0}, 100.0));
}

TEST(LaserSensor, NoiseFreeSquareRoomGivesAnalyticRanges) {
  const double h = 3.0;
  const PlanarWorld room = square_room(h);
  LaserSensorOptions o;
  o.range_sigma = 0.0;
  const LaserSensor laser(o);
  const PlanarPose pose = PlanarPose::from(0.7, -0.4, 0.3);
  const LaserSimFrame f = laser.scan(room, pose, 1, 0);
  ASSERT_EQ(f.scan.size(), 361u);
  EXPECT_DOUBLE_EQ(f.scan.start_bearing_rad, -std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(f.scan.bearing_step_rad, std::numbers::pi / 360);
  for (std::size_t i = 0; i < f.scan.size(); ++i) {
    ASSERT_TRUE(f.scan.valid[i]) << i;
    const double expected = square_range(pose.translation, pose.heading + f.scan.bearing(i), h);
    EXPECT_NEAR(f.scan.ranges[i], expected, 1e-6 * expected) << i;
    // The return lies on the wall the truth names.
    const Eigen::Vector2d p = pose * f.scan.point(i);
    const Wall& wall = room.walls[static_cast<std::size_t>(f.wall[i])];
    EXPECT_NEAR(wall.normal().dot(p - wall.a), 0.0, 1e-5) << i;
  }
}

TEST(LaserSensor, MaxRangeAndSensorOffset) {
  const PlanarWorld room = square_room(3.0);
  LaserSensorOptions o;
  o.range_sigma = 0.0;
  o.max_range = 3.5;
  o.rays = 5;
  o.aperture_rad = std::numbers::pi;
  o.robot_T_sensor = PlanarPose::from(0.5, 0.0, 0.0);
  const LaserSimFrame f = LaserSensor(o).scan(room, PlanarPose::from(-0.5, 0, 0), 1, 0);
  // From the sensor at the origin: right 3, diagonal 3√2 > 3.5 (none), ahead 3.
  EXPECT_FLOAT_EQ(f.scan.ranges[0], 3.0f);
  EXPECT_FALSE(f.scan.valid[1]);
  EXPECT_EQ(f.wall[1], -1);
  EXPECT_FLOAT_EQ(f.scan.ranges[2], 3.0f);
  EXPECT_EQ(f.wall[2], 1);
  EXPECT_EQ(f.wall[4], 2);  // left: +z
}

TEST(LaserSensor, SameSeedSameScanOtherSeedOtherNoise) {
  const PlanarWorld room = square_room(3.0);
  const LaserSensor laser{LaserSensorOptions{}};
  const PlanarPose pose = PlanarPose::from(0.2, 0.1, 1.0);
  const LaserSimFrame a = laser.scan(room, pose, 7, 3), b = laser.scan(room, pose, 7, 3);
  const LaserSimFrame c = laser.scan(room, pose, 8, 3);
  EXPECT_EQ(a.scan.ranges, b.scan.ranges);
  EXPECT_NE(a.scan.ranges, c.scan.ranges);
  double sum2 = 0;
  for (std::size_t i = 0; i < a.scan.size(); ++i) {
    const double e = a.scan.ranges[i] - square_range(pose.translation, pose.heading + a.scan.bearing(i), 3.0);
    sum2 += e * e;
  }
  EXPECT_NEAR(std::sqrt(sum2 / a.scan.size()), 0.01, 0.003);  // σ = 0.01
}

TEST(LaserSensor, BadOptionsThrow) {
  LaserSensorOptions o;
  o.rays = 1;
  EXPECT_THROW(LaserSensor{o}, OptionError);
}

DepthCameraOptions noise_free_camera() {
  DepthCameraOptions o;
  o.noise_per_depth2 = 0.0;
  o.missing = 0.0;
  o.max_depth = 20.0;
  o.min_depth = 0.0;
  return o;
}

TEST(DepthCamera, NoiseFreeSquareRoomGivesAnalyticDepths) {
  const double h = 3.0;
  const PlanarWorld room = square_room(h);
  const DepthCameraOptions o = noise_free_camera();
  const DepthCamera camera(o);
  // At (-2.5, 0.5) looking along +x: the front wall (x = 3) is 5.5 ahead, so at depth 5.5 on
  // every pixel that hits it; the floor at depth camera_height / y_c, the ceiling likewise.
  const DepthFrame f = camera.frame(room, PlanarPose::from(-2.5, 0.5, 0.0), 1, 0);
  ASSERT_EQ(f.depth.size(), 640u * 480u);
  int walls = 0, floors = 0, ceilings = 0;
  for (int v = 0; v < f.height; ++v)
    for (int u = 0; u < f.width; ++u) {
      const double x_c = (u - o.cx) / o.fx, y_c = (v - o.cy) / o.fy;
      // Analytic: the nearest of the four walls along this column's ray, the floor, the ceiling.
      const double angle = -std::atan(x_c);
      const double wall_depth = square_range({-2.5, 0.5}, angle, h) / std::sqrt(1 + x_c * x_c);
      const double up = o.camera_height - y_c * wall_depth;
      double expected = wall_depth;
      int truth = 0;
      if (up < 0) expected = o.camera_height / y_c, truth = kDepthFloor, ++floors;
      else if (up > 2.5) expected = (o.camera_height - o.ceiling_height) / y_c, truth = kDepthCeiling, ++ceilings;
      else ++walls;
      ASSERT_NEAR(f.at(u, v), expected, 2e-6 * expected) << u << "," << v;
      if (std::abs(up) < 1e-9 || std::abs(up - 2.5) < 1e-9) continue;  // the edge: either is right
      if (truth != 0) ASSERT_EQ(f.truth_at(u, v), truth) << u << "," << v;
      else ASSERT_GE(f.truth_at(u, v), 10) << u << "," << v;
    }
  EXPECT_GT(walls, 1000);
  EXPECT_GT(floors, 1000);
  EXPECT_GT(ceilings, 1000);
  // The centre looks straight at wall 11 (x = 3): depth 5.5.
  EXPECT_NEAR(f.at(320, 240), 5.5, 1e-5);
  EXPECT_EQ(f.truth_at(320, 240), 11);
}

TEST(DepthCamera, LowWallIsSeenOverFromAbove) {
  PlanarWorld world = square_room(3.0);
  Wall low = Wall::between(20, {2.0, 1.0}, {2.0, -1.0});  // faces −x, towards the camera
  low.height = 0.5;
  world.walls.push_back(low);
  const DepthCamera camera(noise_free_camera());
  const DepthFrame f = camera.frame(world, PlanarPose::from(0, 0, 0), 1, 0);
  // Centre column: rows below the low wall's top see it at depth 2, rows above see wall 11 at 3.
  EXPECT_EQ(f.truth_at(320, 479), 20);  // y_c = 0.4566 > 0.25: floor in front would be at 2.19 > 2
  EXPECT_NEAR(f.at(320, 479), 2.0, 1e-6);
  EXPECT_EQ(f.truth_at(320, 240), 11);
  EXPECT_NEAR(f.at(320, 240), 3.0, 1e-6);
}

TEST(DepthCamera, NoiseGrowsWithDepthSquaredMissingReturnsSeeded) {
  const PlanarWorld room = square_room(3.0);
  DepthCameraOptions o;
  o.missing = 0.1;
  const DepthCamera camera(o);
  const PlanarPose pose = PlanarPose::from(-2.0, 0.0, 0.0);  // wall 11 at depth 5 ahead
  const DepthFrame a = camera.frame(room, pose, 3, 4), b = camera.frame(room, pose, 3, 4);
  EXPECT_EQ(a.depth, b.depth);
  EXPECT_EQ(a.truth, b.truth);
  double sum2 = 0;
  int n = 0, missing = 0, wall_pixels = 0;
  for (int v = 200; v < 280; ++v)
    for (int u = 300; u < 340; ++u) {
      if (a.truth_at(u, v) != 11) continue;
      ++wall_pixels;
      const double z = 5.0;  // the wall x = 3 is perpendicular to the optical axis: one depth
      if (a.at(u, v) == 0.0f) {
        ++missing;
        continue;
      }
      sum2 += (a.at(u, v) - z) * (a.at(u, v) - z);
      ++n;
    }
  ASSERT_EQ(wall_pixels, 80 * 40);
  EXPECT_NEAR(std::sqrt(sum2 / n), 1.425e-3 * 25.0, 0.1 * 1.425e-3 * 25.0);
  EXPECT_NEAR(static_cast<double>(missing) / wall_pixels, 0.1, 0.02);
}

}  // namespace
}  // namespace relslam::sim
