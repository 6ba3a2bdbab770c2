// relative_plane.observed_anchor (beyond Rule 4, adaptive preset): X0 is put in the start frame
// only by a first reading's uncut end or by the lines of two non-parallel first readings.
#include "relslam/plane/rlt_xpoints_s.hpp"

#include "plane_world_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace relslam::plane {
namespace {

// The four planes problem (Map A, one loop) whose first frame shows each wall only as a piece the
// sensor cut at both ends (45 % of the wall, from 5, 20, 35 and 50 % along it); every later
// frame shows the walls whole.
test::PlaneRun four_planes_first_seen_in_pieces() {
  const std::vector<test::Wall> walls = test::four_planes_walls();
  test::PlaneRun world =
      test::run_path(walls, test::four_planes_path(1, 0.1, 5 * std::numbers::pi / 180), {.always = true});
  double from = 0.05;
  for (PlaneObject& p : world.frames.front().planes) {
    const Eigen::Vector2d a = p.a, b = p.b;
    p.a = a + from * (b - a);
    p.b = a + (from + 0.45) * (b - a);
    p.a_cut = p.b_cut = true;
    from += 0.15;  // a different piece of each wall, so the errors along them do not cancel
  }
  return world;
}

// The largest position error of a valid pose and how many there were.
std::pair<double, int> run(const test::PlaneRun& world, const RelativePlaneOptions& options) {
  RltXPointsS slam(options, world.world_T_robot.front());
  double worst = 0;
  int valid = 0;
  for (std::size_t t = 0; t < world.frames.size(); ++t) {
    const RelativePlaneStep step = slam.step(world.frames[t]);
    if (!step.pose_valid) continue;
    ++valid;
    worst = std::max(worst, (step.world_T_robot.translation - world.world_T_robot[t].translation).norm());
  }
  return {worst, valid};
}

// Anchored on the pieces as seen (the adaptive preset's default) X0 and every pose is off along
// the walls; on the pieces' lines, which cross at the corners, X0 is exact and so is every pose.
TEST(ObservedAnchor, TwoNonParallelFirstReadingsCutAtBothEndsPlaceX0) {
  const test::PlaneRun world = four_planes_first_seen_in_pieces();
  RelativePlaneOptions options = preset_options(Preset::Adaptive);
  const auto [guessed_worst, guessed_valid] = run(world, options);
  ASSERT_GT(guessed_valid, 0);
  EXPECT_GT(guessed_worst, 0.3);
  options.observed_anchor = true;
  const auto [worst, valid] = run(world, options);
  EXPECT_GE(valid, guessed_valid);
  EXPECT_LT(worst, 1e-6);
}

// One wall only in the first frame, cut at both ends: nothing fixes where along it the start
// was, so X0 waits and no pose is given, rather than one resting on the guess.
TEST(ObservedAnchor, OneFirstReadingCutAtBothEndsGivesNoPose) {
  test::PlaneRun world = four_planes_first_seen_in_pieces();
  world.frames.front().planes.resize(1);
  RelativePlaneOptions options = preset_options(Preset::Adaptive);
  options.observed_anchor = true;
  const auto [worst, valid] = run(world, options);
  EXPECT_EQ(valid, 0);
  EXPECT_EQ(worst, 0);
}

}  // namespace
}  // namespace relslam::plane
