#include "relslam/point/point_matching.hpp"

#include "seeded_random.hpp"

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include <set>

namespace relslam::point {
namespace {

// Two landmarks 0.3 apart, the robot turning so each moves ~0.6 between frames: without
// motion compensation the nearest previous observation is the other landmark's.
TEST(PointMatcher, MotionCompensationKeepsCloseLandmarksApart) {
  test::SeededRandom rng(701);
  std::vector<Eigen::Vector3d> world;
  for (int i = 0; i < 40; ++i) world.emplace_back(rng.uniform(-40, 40), rng.uniform(-4, 4), rng.uniform(20, 95));
  world.push_back({0.0, 0.0, 60.0});
  world.push_back({0.3, 0.0, 60.0});
  auto pose = [](int k) {
    return Rigid3{rotation_about(Eigen::Vector3d::UnitY(), 0.01 * k), Eigen::Vector3d(0, 0, 0.3 * k)};
  };

  for (bool compensate : {true, false}) {
    PointSlamOptions o;
    o.compensate_motion = compensate;
    PointMatcher matcher(o);
    auto global_index =
        spatial::make_global_index(spatial::GlobalIndexKind::Incremental, o.global_cell_size, o.global_bound);
    auto& global = *global_index;
    std::vector<RltPoint> points;  // landmark i is RltPoint i
    std::vector<LocalCandidate> candidates;
    int swaps = 0;
    for (int k = 0; k < 6; ++k) {
      std::vector<Eigen::Vector3d> obs;
      for (const auto& w : world) obs.push_back(pose(k).inverse_apply(w));
      if (k > 0) {
        matcher.prepare(candidates, k);
        const MatchResult& r = matcher.match(obs, k, global, points, pose(k - 1));
        for (int i = 0; i < static_cast<int>(obs.size()); ++i) swaps += r.assigned[i] != i;
        if (compensate && k > 1) {
          EXPECT_TRUE(r.motion_estimated);
          const Rigid3 truth = pose(k).inverse() * pose(k - 1);
          EXPECT_LT((r.motion.translation - truth.translation).norm(), 1e-9);
        }
      }
      candidates.clear();
      points.resize(obs.size());
      for (int i = 0; i < static_cast<int>(obs.size()); ++i) {
        points[i].id = i;
        points[i].observations.push({obs[i], k});
        candidates.push_back({i, obs[i], k});
      }
    }
    if (compensate) {
      EXPECT_EQ(swaps, 0);
    } else {
      EXPECT_GT(swaps, 0) << "the thesis's plain nearest match confuses the pair";
    }
  }
}

TEST(PointMatcher, GlobalMatchingFindsAMappedPointThroughThePose) {
  PointSlamOptions o;
  PointMatcher matcher(o);
  auto global_index =
      spatial::make_global_index(spatial::GlobalIndexKind::Incremental, o.global_cell_size, o.global_bound);
  auto& global = *global_index;
  std::vector<RltPoint> points(1);
  points[0].id = 0;
  points[0].observations.push({Eigen::Vector3d(0, 0, 10), 0});
  points[0].global = {5, 0, 30};
  points[0].has_global = true;
  global.place(0, points[0].global);
  const Rigid3 world_T_robot{Eigen::Matrix3d::Identity(), Eigen::Vector3d(5, 0, 10)};
  matcher.prepare({}, 50);
  const MatchResult& r = matcher.match({Eigen::Vector3d(0.5, 0, 20.5)}, 50, global, points, world_T_robot);
  EXPECT_EQ(r.assigned, std::vector<PointId>{0});
  EXPECT_EQ(r.global, 1);
  points[0].dynamic = true;  // flagged movers are never matched globally
  matcher.prepare({}, 51);
  EXPECT_EQ(matcher.match({Eigen::Vector3d(0.5, 0, 20.5)}, 51, global, points, world_T_robot).assigned,
            std::vector<PointId>{kNone});
}

TEST(PointMatcher, OneObservationPerPointAndViceVersa) {
  PointSlamOptions o;
  o.compensate_motion = false;
  PointMatcher matcher(o);
  auto global_index =
      spatial::make_global_index(spatial::GlobalIndexKind::Incremental, o.global_cell_size, o.global_bound);
  auto& global = *global_index;
  std::vector<RltPoint> points(1);
  points[0].observations.push({Eigen::Vector3d(0, 0, 10), 0});
  matcher.prepare({{0, {0, 0, 10}, 0}}, 1);
  // Two observations near one candidate: the closer one gets it, the other is new.
  const MatchResult& r =
      matcher.match({Eigen::Vector3d(0.5, 0, 10), Eigen::Vector3d(0.1, 0, 10)}, 1, global, points, Rigid3::identity());
  EXPECT_EQ(r.assigned, (std::vector<PointId>{kNone, 0}));
}

}  // namespace
}  // namespace relslam::point

namespace relslam::point {
namespace {

// Brute force: every (observation, candidate) pair within the bound, closest first.
std::vector<PointId> brute_force_matches(const std::vector<Eigen::Vector3d>& obs,
                                         const std::vector<LocalCandidate>& cands, double bound) {
  struct Pair {
    double d;
    int i;
    PointId id;
  };
  std::vector<Pair> pairs;
  for (int i = 0; i < static_cast<int>(obs.size()); ++i)
    for (const LocalCandidate& c : cands)
      if (const double d = (obs[i] - c.p).norm(); d <= bound) pairs.push_back({d, i, c.id});
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
    return a.d != b.d ? a.d < b.d : (a.i != b.i ? a.i < b.i : a.id < b.id);
  });
  std::vector<PointId> assigned(obs.size(), kNone);
  std::set<PointId> taken;
  for (const Pair& p : pairs)
    if (assigned[p.i] == kNone && !taken.count(p.id)) assigned[p.i] = p.id, taken.insert(p.id);
  return assigned;
}

TEST(PointMatcher, EveryLocalIndexGivesTheBruteForceMatches) {
  test::SeededRandom rng(702);
  for (spatial::LocalIndexKind kind :
       {spatial::LocalIndexKind::Quadtree, spatial::LocalIndexKind::Octree, spatial::LocalIndexKind::KdTree})
    for (int trial = 0; trial < 10; ++trial) {
      std::vector<LocalCandidate> cands;
      std::vector<Eigen::Vector3d> obs;
      for (int i = 0; i < 300; ++i) {
        cands.push_back({i, {rng.uniform(-60, 60), rng.uniform(-5, 5), rng.uniform(1, 100)}, 9});
        if (rng.uniform() < 0.8)
          obs.push_back(cands.back().p + 0.5 * Eigen::Vector3d(rng.gaussian(), rng.gaussian(), rng.gaussian()));
      }
      PointSlamOptions o;
      o.compensate_motion = false;  // the thesis's single pass: exactly the brute-force rule
      o.local_index = kind;
      PointMatcher matcher(o);
      auto global =
          spatial::make_global_index(spatial::GlobalIndexKind::Incremental, o.global_cell_size, o.global_bound);
      std::vector<RltPoint> points(cands.size());
      for (const LocalCandidate& c : cands) points[c.id].observations.push({c.p, 9});
      matcher.prepare(cands, 10);
      EXPECT_EQ(matcher.match(obs, 10, *global, points, Rigid3::identity()).assigned,
                brute_force_matches(obs, cands, o.local_bound))
          << spatial::to_string(kind) << " trial " << trial;
    }
}

}  // namespace
}  // namespace relslam::point
