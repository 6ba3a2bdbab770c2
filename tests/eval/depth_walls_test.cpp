// The simulated depth camera's frames carry the walls EM2 finds in its 640 × 480 images
// (planar.depth_planes "extracted", the default; thesis 3.5 at sensor density, then 4.5's wall
// conversion): each extracted wall lies near the wall most of its pixels see, with that wall's
// id as truth, and Relative Plane maps them.
#include "test_support.hpp"
#include "wall_distance.hpp"

#include "relslam/eval/algorithms/registry.hpp"
#include "relslam/eval/sources/planar_simulation_source.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace relslam::eval {
namespace {

LoadedScenario depth_scenario(const std::string& planar) {
  return parse_scenario(R"({"kind": "planar", "seed": 1, "planar": {)" + planar + R"("map": "e_motion_room",
      "sensor": "depth", "iterations": 90}, "algorithms": ["relative_plane"]})",
                        "depth_walls.json");
}

using test::line_distance;

TEST(DepthWalls, KinectNoiseWallsLieOnTheirTrueWallsAndRelativePlaneMapsThem) {
  const LoadedScenario loaded = depth_scenario("");
  PlanarSimulationSource source(loaded);
  ASSERT_EQ(source.frame_columns(), (std::vector<std::string>{"t_extract_ms", "walls"}));
  auto slam = make_plane_algorithm("relative_plane", {loaded.scenario, source.start()});
  int frames = 0, valid = 0, unknown = 0;
  long long walls = 0;
  double worst = 0;
  source.stream([&](const PlaneFrame& frame, const PlaneTruthFrame& truth, const std::vector<CsvField>& measured) {
    ASSERT_EQ(frame.planes.size(), truth.planes.size());
    EXPECT_EQ(std::get<long long>(measured[1]), static_cast<long long>(frame.planes.size()));
    for (std::size_t i = 0; i < frame.planes.size(); ++i) {
      const int id = truth.planes[i].wall_id;
      if (id < 0) {
        ++unknown;
        continue;
      }
      const PlaneObject& wall = source.walls()[static_cast<std::size_t>(id)];
      for (const Eigen::Vector2d& end : {frame.planes[i].a, frame.planes[i].b})
        worst = std::max(worst, line_distance(truth.world_T_robot * end, wall));
      // Standing on the floor like the plane sensor's walls: the image's heights moved up by the
      // camera's, within the room.
      EXPECT_GE(frame.planes[i].y_lo, -0.1);
      EXPECT_LE(frame.planes[i].y_hi, loaded.scenario.planar.depth.ceiling_height + 0.1);
      EXPECT_LT(frame.planes[i].y_lo, frame.planes[i].y_hi);
    }
    walls += static_cast<long long>(frame.planes.size());
    slam->step(frame);
    slam->read_out();
    valid += slam->pose().has_value();
    ++frames;
  });
  EXPECT_EQ(frames, 90);
  EXPECT_GT(walls, frames);  // a wall or more per image
  EXPECT_EQ(unknown, 0);
  // Measured: every end within 0.47 of its wall's line (at the Kinect's noise a far piece's ends
  // lie up to 8 units out, where the depth σ is 9 cm), 6 of 90 frames with a pose: Relative
  // Plane rarely gets a pose from the camera's walls, not yet explained
  // (docs/algorithms/range-sensors.md).
  EXPECT_LT(worst, 0.6);
  EXPECT_GE(valid, 4);
}

TEST(DepthWalls, SensorPlanesOnRequest) {
  const LoadedScenario loaded = depth_scenario(R"("depth_planes": "sensor", )");
  PlanarSimulationSource source(loaded);
  EXPECT_TRUE(source.frame_columns().empty() || source.frame_columns()[0] != "t_extract_ms");
}

}  // namespace
}  // namespace relslam::eval
