#pragma once
// A test-only plane world: walls, a robot path, and the noise-free full-size PlaneFrames a
// robot on that path would report (the `full_size` mode of the simulator, which lives a layer
// up). Standard library and relslam/core only, so relslam_slam_tests stays one layer.

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"

#include <Eigen/Core>

#include <vector>

namespace relslam::plane::test {

// A wall in the world: `a` to `b` ordered so its front normal Rot(+90°)(b − a) faces the
// walkable side (thesis 4.4.2).
struct Wall {
  Eigen::Vector2d a;
  Eigen::Vector2d b;
};

// Which walls the robot reports, always whole (full size): every front-facing wall, or those
// with some part in the robot-frame box near ≤ x ≤ far, |z| ≤ half_width (Map B's
// scripted window [x_r + 1, x_r + 8], turned with the robot).
struct Visibility {
  bool always = false;
  double near = 1;
  double far = 8;
  double half_width = 3;
};

// A path of in-place turns and straight moves, one pose per iteration (thesis 4.4.2).
class PathBuilder {
 public:
  explicit PathBuilder(const PlanarPose& start) : poses_{start} {}
  PathBuilder& move(double distance, double step);
  PathBuilder& turn(double angle_rad, double step_rad);
  const std::vector<PlanarPose>& poses() const { return poses_; }

 private:
  std::vector<PlanarPose> poses_;
};

struct PlaneRun {
  std::vector<PlanarPose> world_T_robot;   // truth, one per iteration
  std::vector<PlaneFrame> frames;          // what the robot reports
  std::vector<std::vector<int>> wall_ids;  // the wall of each reported plane
};

// What the robot at world_T_robot reports at `iteration`, in wall order.
PlaneFrame observe(const std::vector<Wall>& walls, const PlanarPose& world_T_robot, int iteration,
                   const Visibility& visibility, std::vector<int>* wall_ids = nullptr);
PlaneRun run_path(const std::vector<Wall>& walls, const std::vector<PlanarPose>& path, const Visibility& visibility);

// Map A, the four planes problem: four walls of length 8 at distance 5.
std::vector<Wall> four_planes_walls();
// Its square path: from (−2, −2) facing +x, MOVE 4, TURN +90° four times a loop.
std::vector<PlanarPose> four_planes_path(int loops, double step, double turn_step_rad);
// A Map B/C-like hallway along +x of width 3, eight 4-long segments a side, and an end wall.
std::vector<Wall> hallway_walls();

}  // namespace relslam::plane::test
