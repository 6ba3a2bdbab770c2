#pragma once
// What a picture of a planar run shows at one iteration (thesis Fig. 67), as plain data: the
// replay (plane_replay.hpp) fills it, the drawing (planar_render.hpp) draws it. Its own header so
// the replay needs nothing of the drawing.

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"
#include "relslam/sim/viewing_frustum.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace relslam::eval {

// One group of planes (thesis RltXPoint, 4.4.3.2) where the map placed it.
struct PlanarSceneGroup {
  int id = 0;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // world (x, z) of the group's origin
  std::vector<Eigen::Vector2d> member_midpoints;       // of its mapped member planes, world
};

// Everything in the world frame (x, z).
struct PlanarScene {
  std::string title;                  // top-left caption
  std::vector<PlaneObject> walls;     // true
  std::vector<PlaneObject> mapped;    // the algorithm's map now
  std::vector<PlaneObject> readings;  // this iteration's observations placed at the estimated pose
  std::vector<PlanarSceneGroup> groups;
  std::optional<PlanarPose> true_pose;  // world_T_robot
  std::optional<PlanarPose> estimated_pose;
  std::vector<Eigen::Vector2d> true_path;  // up to this iteration
  std::vector<Eigen::Vector2d> estimated_path;
  // The sensor's footprint, drawn at the estimated pose; none when the walls are not seen
  // through a frustum (scripted or always-visible maps, thesis 4.3.1-4.3.2).
  std::optional<sim::ViewingFrustum> frustum;
};

}  // namespace relslam::eval
