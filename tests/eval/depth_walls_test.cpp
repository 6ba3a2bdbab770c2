// The simulated depth camera's frames carry the walls EM2 finds in its 640 × 480 images
// (planar.depth_planes "extracted", the default; thesis 3.5 at sensor density, then 4.5's wall
// conversion): each extracted wall lies near the wall most of its pixels see, with that wall's
// id as truth, once per image, and Relative Plane runs on them (why it gets few poses from
// them: docs/algorithms/range-sensors.md).
#include "test_support.hpp"
#include "wall_distance.hpp"

#include "relslam/eval/algorithms/registry.hpp"
#include "relslam/eval/sources/planar_simulation_source.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <set>
#include <string>

namespace relslam::eval {
namespace {

// The default suite's images: the first 90 of Map E's path. The long build
// (RELSLAM_DEPTH_WALLS_LONG) takes the whole loop of scenarios/p-depth-room.json.
// Over the whole loop (measured, 1441 images at Kinect noise): 2126 walls, none twice in an
// image, but 4 more than 30° off their wall, each also with an end more than 0.4 off its line
// (images 591, 717 and 720 on wall 7, 1298 on wall 5, up to 89°): the goal, every wall within
// 30°, is not met there yet, and the long build bounds what is measured. Noise-free over the
// loop: 2320 walls, 93 % exact, 27 more than 25° off (up to 89°).
#ifdef RELSLAM_DEPTH_WALLS_LONG
const std::string kImages = R"("loops": 1)";
constexpr int kFrames = 1441;
constexpr int kTiltedAtMost = 4;
constexpr int kNoiseFreeTiltedAtMost = 27;
#else
const std::string kImages = R"("iterations": 90)";
constexpr int kFrames = 90;
constexpr int kTiltedAtMost = 0;
constexpr int kNoiseFreeTiltedAtMost = 0;
#endif

LoadedScenario depth_scenario(const std::string& planar) {
  return parse_scenario(R"({"kind": "planar", "seed": 1, "planar": {)" + planar + R"("map": "e_motion_room",
      "sensor": "depth", )" + kImages + R"(}, "algorithms": ["relative_plane"]})",
                        "depth_walls.json");
}

using test::line_distance;

// The angle between an observed wall put into the world and its true wall, degrees (0–90).
double angle_off_deg(const PlaneObject& seen, const PlanarPose& world_T_robot, const PlaneObject& wall) {
  const Eigen::Vector2d u = (world_T_robot * seen.b - world_T_robot * seen.a).normalized();
  const Eigen::Vector2d w = wall.tangent();
  return std::asin(std::min(1.0, std::abs(u.x() * w.y() - u.y() * w.x()))) * 180.0 / std::numbers::pi;
}

TEST(DepthWalls, KinectNoiseWallsLieOnTheirTrueWallsOnceEach) {
  const LoadedScenario loaded = depth_scenario("");
  PlanarSimulationSource source(loaded);
  ASSERT_EQ(source.frame_columns(), (std::vector<std::string>{"t_extract_ms", "walls"}));
  auto slam = make_plane_algorithm("relative_plane", {loaded.scenario, source.start()});
  int frames = 0, unknown = 0, twice = 0;
  long long walls = 0;
  double worst = 0, worst_angle = 0;
  int tilted = 0, off_line = 0;  // walls more than 30° off, with an end more than 0.4 off the line
  std::string outliers;
  source.stream([&](const PlaneFrame& frame, const PlaneTruthFrame& truth, const std::vector<CsvField>& measured) {
    ASSERT_EQ(frame.planes.size(), truth.planes.size());
    EXPECT_EQ(std::get<long long>(measured[1]), static_cast<long long>(frame.planes.size()));
    std::set<int> seen;
    for (std::size_t i = 0; i < frame.planes.size(); ++i) {
      const int id = truth.planes[i].wall_id;
      if (id < 0) {
        ++unknown;
        continue;
      }
      twice += !seen.insert(id).second;
      const PlaneObject& wall = source.walls()[static_cast<std::size_t>(id)];
      double end_off = 0;
      for (const Eigen::Vector2d& end : {frame.planes[i].a, frame.planes[i].b})
        end_off = std::max(end_off, line_distance(truth.world_T_robot * end, wall));
      const double angle = angle_off_deg(frame.planes[i], truth.world_T_robot, wall);
      worst = std::max(worst, end_off), worst_angle = std::max(worst_angle, angle);
      tilted += angle >= 30.0, off_line += end_off >= 0.4;
      if (angle >= 30.0 || end_off >= 0.4)
        outliers += "image " + std::to_string(frames) + " wall " + std::to_string(id) + ": " + std::to_string(angle) +
                    " deg, end " + std::to_string(end_off) + ", length " +
                    std::to_string((frame.planes[i].b - frame.planes[i].a).norm()) + "\n";
      // Standing on the floor like the plane sensor's walls: the image's heights moved up by the
      // camera's, within the room.
      EXPECT_GE(frame.planes[i].y_lo, -0.1);
      EXPECT_LE(frame.planes[i].y_hi, loaded.scenario.planar.depth.ceiling_height + 0.1);
      EXPECT_LT(frame.planes[i].y_lo, frame.planes[i].y_hi);
    }
    walls += static_cast<long long>(frame.planes.size());
    slam->step(frame);
    slam->read_out();
    ++frames;
  });
  EXPECT_EQ(frames, kFrames);
  EXPECT_GE(walls, frames);  // a wall or more per image
  EXPECT_EQ(unknown, 0);
  // With d_in growing as the camera's 3σ (σ = 1.425e-3 z²) and strips dropped: every wall once
  // per image (with a fixed 5 cm, 52 of 153 walls in these 90 images were further pieces of a
  // wall already reported, tilted up to 78°), each within 27° of its true wall (a 0.7-unit
  // sliver of wall 5 at the image border in image 0; every other within 0.07°), every end within
  // 0.24 of its wall's line.
  EXPECT_EQ(twice, 0);
  EXPECT_LE(tilted, kTiltedAtMost);
  EXPECT_LE(off_line, kTiltedAtMost);
  std::cout << frames << " images, " << walls << " walls, " << twice << " seen twice, worst angle " << worst_angle
            << " deg, worst end " << worst << "; " << tilted << " walls 30 deg or more off, " << off_line
            << " with an end 0.4 or more off the line\n" << outliers;
}

// Noise-free images: the walls EM2 reports are their true walls, nearly all exactly. Before the
// strip check of the dense extraction, the floor's and ceiling's image rows at one depth near the camera's 8-unit limit (rows
// the floor's growth in the summary did not reach) and a far wall's column at that depth were
// taken for one more wall facing the camera, 90° off the wall most of its pixels see; Relative
// Plane then got no pose at all.
TEST(DepthWalls, NoiseFreeWallsAreExactAndNoneIsMadeOfStrips) {
  const LoadedScenario loaded = depth_scenario(R"("depth": {"noise_per_depth2": 0, "missing": 0}, )");
  PlanarSimulationSource source(loaded);
  int frames = 0, walls = 0, exact = 0;
  double worst_angle = 0;
  int tilted = 0;  // walls 25° or more off
  source.stream([&](const PlaneFrame& frame, const PlaneTruthFrame& truth, const std::vector<CsvField>&) {
    for (std::size_t i = 0; i < frame.planes.size(); ++i) {
      const int id = truth.planes[i].wall_id;
      ASSERT_GE(id, 0);
      const PlaneObject& wall = source.walls()[static_cast<std::size_t>(id)];
      double off = 0;
      for (const Eigen::Vector2d& end : {frame.planes[i].a, frame.planes[i].b})
        off = std::max(off, line_distance(truth.world_T_robot * end, wall));
      exact += off < 1e-3;
      const double angle = angle_off_deg(frame.planes[i], truth.world_T_robot, wall);
      worst_angle = std::max(worst_angle, angle);
      tilted += angle >= 25.0;
      ++walls;
    }
    ++frames;
  });
  EXPECT_EQ(frames, kFrames);
  EXPECT_GE(walls, frames);
  // Measured: 92 % of the walls exact to 1e-3 (75 % before the strip check), the rest pieces
  // of the far end of wall 0 at 7–8 units, 13–14° off, one 20.7° (90° before the strip check;
  // 13.7° at most before every pixel asked every plane).
  EXPECT_LE(tilted, kNoiseFreeTiltedAtMost);
  EXPECT_GE(exact, walls * 9 / 10);
  std::cout << frames << " images, " << walls << " walls, " << exact << " exact, worst angle " << worst_angle
            << " deg, " << tilted << " 25 deg or more off\n";
}

TEST(DepthWalls, SensorPlanesOnRequest) {
  const LoadedScenario loaded = depth_scenario(R"("depth_planes": "sensor", )");
  PlanarSimulationSource source(loaded);
  EXPECT_TRUE(source.frame_columns().empty() || source.frame_columns()[0] != "t_extract_ms");
}

}  // namespace
}  // namespace relslam::eval
