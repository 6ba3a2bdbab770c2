// RltXMMPoint (thesis 4.3.6, Rules 23–27): the motion model tracks the robot from one
// partial plane under forward-only motion and grows the plane as more of it comes into view.
#include "relslam/plane/rlt_xmm_point.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace relslam::plane {
namespace {

constexpr double kExact = 1e-9;
constexpr double kDeg = std::numbers::pi / 180.0;

// A long wall across the view at x = 5, facing the robot at the origin (normal −x).
const Eigen::Vector2d kWallA{5, -10}, kWallB{5, 10};

// The wall as a frustum of half-angle 30° sees it from `world_T_robot`: the chord between the
// two edge rays, cut to the wall (robot frame). Robots here always face the wall.
PlaneObject seen_from(const PlanarPose& world_T_robot, int iteration) {
  std::vector<double> z;
  for (double edge : {-30 * kDeg, 30 * kDeg}) {
    const double psi = world_T_robot.heading + edge;
    const Eigen::Vector2d ray{std::cos(psi), std::sin(psi)};
    const double t = (kWallA.x() - world_T_robot.translation.x()) / ray.x();
    z.push_back(std::clamp(world_T_robot.translation.y() + t * ray.y(), kWallA.y(), kWallB.y()));
  }
  const PlaneObject world{{5, std::min(z[0], z[1])}, {5, std::max(z[0], z[1])}};
  PlaneObject robot = world.transformed(world_T_robot.inverse());
  robot.iteration = iteration;
  return robot;
}

// The robot's path: turning in place, driving forward, turning again.
std::vector<PlanarPose> path() {
  std::vector<PlanarPose> poses{PlanarPose::from(0, 0, 0)};
  const auto step = [&](double forward, double turn_deg) {
    PlanarPose p = poses.back();
    p.translation += forward * Eigen::Vector2d(std::cos(p.heading), std::sin(p.heading));
    p.heading = wrap_angle(p.heading + turn_deg * kDeg);
    poses.push_back(p);
  };
  for (int k = 0; k < 20; ++k) step(0, 1.5);   // to 30°
  for (int k = 0; k < 20; ++k) step(0.05, 0);  // one unit forward at 30°
  for (int k = 0; k < 10; ++k) step(0, -1.5);  // back to 15°
  return poses;
}

struct Tracked {
  std::vector<RltPlane> planes;
  RltXMMPoint mm;
};

// The map knows the wall as the first pose saw it; the motion model starts there.
Tracked track(const std::vector<PlanarPose>& poses, int observed, const MotionModelOptions& options = {}) {
  std::vector<RltPlane> planes;
  planes.emplace_back(0, seen_from(poses[0], 0), 1200);
  for (int t = 1; t < observed; ++t) planes[0].add(seen_from(poses[t], t));
  planes[0].join(0, 0);
  RltXMMPoint mm(0, 0, poses[0], 0, seen_from(poses[0], 0).transformed(poses[0]));
  mm.compute(planes, options);
  return {std::move(planes), std::move(mm)};
}

TEST(RltXMMPoint, TracksTurnsAndForwardMotionExactlyFromOnePlane) {
  const std::vector<PlanarPose> poses = path();
  for (int observed : {1, 10, 25, 40, 51}) {
    const Tracked t = track(poses, observed);
    const int last = observed - 1;
    ASSERT_TRUE(t.mm.world_T_robot(last).has_value()) << observed;
    const PlanarPose got = *t.mm.world_T_robot(last);
    EXPECT_LT((got.translation - poses[last].translation).norm(), kExact) << "iteration " << last;
    EXPECT_NEAR(wrap_angle(got.heading - poses[last].heading), 0, kExact) << "iteration " << last;
    EXPECT_FALSE(t.mm.world_T_robot(last + 1).has_value());  // only where the plane was seen
  }
}

TEST(RltXMMPoint, GrowsThePlaneToEverythingSeenAndKeepsTheEndThatDidNotMove) {
  const std::vector<PlanarPose> poses = path();
  const Tracked t = track(poses, static_cast<int>(poses.size()));
  // The true extent seen: the union of every chord (the map's start is inside it).
  const PlaneObject first = seen_from(poses[0], 0).transformed(poses[0]);
  double lo = first.a.y(), hi = first.b.y();
  for (std::size_t k = 0; k < poses.size(); ++k) {
    const PlaneObject w = seen_from(poses[k], 0).transformed(poses[k]);
    lo = std::min({lo, w.a.y(), w.b.y()});
    hi = std::max({hi, w.a.y(), w.b.y()});
  }
  ASSERT_GT(hi, first.b.y() + 1);  // turning left the view swept up the wall: it grew at one end only
  ASSERT_EQ(lo, first.a.y());
  const RltXPointRef* ref = t.planes[0].ref(0);
  ASSERT_NE(ref, nullptr);
  EXPECT_TRUE(ref->valid);
  EXPECT_NEAR(ref->max_length, hi - lo, kExact);
  const PlaneObject mapped = PlaneObject::from_pose(t.mm.anchor() * ref->pose, ref->max_length);
  EXPECT_LT((mapped.a - Eigen::Vector2d(5, lo)).norm(), kExact);
  EXPECT_LT((mapped.b - Eigen::Vector2d(5, hi)).norm(), kExact);
  // The wall's normal is −x, so its left end (key point 1) is the lower one, which did not move.
  EXPECT_EQ(ref->key_point, KeyPoint::Left);
  EXPECT_FALSE(ref->size_static);
}

TEST(RltXMMPoint, GrowthThresholdIgnoresSmallOverreach) {
  const std::vector<PlanarPose> poses = path();
  MotionModelOptions options;
  options.grow_threshold = 100;  // nothing ever reaches that far past the known extent
  const Tracked t = track(poses, static_cast<int>(poses.size()), options);
  EXPECT_NEAR(t.planes[0].ref(0)->max_length, seen_from(poses[0], 0).length(), kExact);
  EXPECT_TRUE(t.planes[0].ref(0)->size_static);
}

TEST(RltXMMPoint, AnEndedTrackIgnoresLaterObservations) {
  const std::vector<PlanarPose> poses = path();
  Tracked t = track(poses, 20);
  t.mm.end(19);
  const double length = t.planes[0].ref(0)->max_length;
  for (int k = 20; k < static_cast<int>(poses.size()); ++k) t.planes[0].add(seen_from(poses[k], k));
  t.mm.compute(t.planes, {});
  EXPECT_EQ(t.planes[0].ref(0)->max_length, length);
  EXPECT_EQ(t.mm.last()->iteration, 19);
}

TEST(RltXMMPoint, NearlyParallelHeadingsMoveTowardsThePlaneOnly) {
  // Rule 25: driving at 70° to the wall's normal the along-wall motion is not trusted: the
  // tracked distance to the wall stays exact, the motion along it is dropped.
  std::vector<PlanarPose> poses{PlanarPose::from(0, 0, 70 * kDeg)};
  for (int k = 0; k < 10; ++k) {
    PlanarPose p = poses.back();
    p.translation += 0.05 * Eigen::Vector2d(std::cos(p.heading), std::sin(p.heading));
    poses.push_back(p);
  }
  // At 70° the frustum's left edge looks past the wall; what it sees is its lower part.
  const Tracked t = track(poses, static_cast<int>(poses.size()));
  const PlanarPose got = *t.mm.world_T_robot(static_cast<int>(poses.size()) - 1);
  EXPECT_NEAR(got.translation.x(), poses.back().translation.x(), kExact);
  EXPECT_NEAR(got.translation.y(), 0, kExact);
  EXPECT_GT(poses.back().translation.y(), 0.4);
}

}  // namespace
}  // namespace relslam::plane
