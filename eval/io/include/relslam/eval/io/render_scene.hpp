#pragma once
// What a picture of a point run shows at one iteration (thesis Figs 127-129, 153-162), as plain
// data: the replay (point_replay.hpp) fills it, the drawing (map_render.hpp) draws it. Its own
// header so the replay needs nothing of the drawing.

#include "relslam/core/rigid.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace relslam::eval {

// One map landmark as the algorithm holds it (world frame, our axes).
struct SceneLandmark {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  int id = 0;
  int group = -1;        // the group that maps it (owner); -1 none (EKF landmarks)
  bool final = false;    // mapped by a final group (black label) rather than a temporary one (red)
  bool dynamic = false;  // flagged dynamic by RltBinning (thesis 6.5.3)
};

struct SceneGroup {
  int id = 0;
  bool final = false;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // of its members' map positions: rendering only (thesis Fig 129)
};

// The sensor's field of view, drawn as a wedge in front of a pose (sim.frustum).
struct SceneFrustum {
  double near = 1.0;
  double far = 100.0;
  double half_angle_rad = 0.785398;
};

struct RenderScene {
  std::string title;                         // top-left caption
  std::vector<Eigen::Vector3d> true_points;  // every true landmark at this iteration
  std::vector<bool> true_dynamic;            // parallel to true_points
  std::vector<SceneLandmark> landmarks;
  std::vector<SceneGroup> groups;
  std::optional<Rigid3> true_pose;  // world_T_robot
  std::optional<Rigid3> estimated_pose;
  std::vector<Eigen::Vector3d> true_path;  // up to this iteration
  std::vector<Eigen::Vector3d> estimated_path;
  SceneFrustum frustum;
};

}  // namespace relslam::eval
