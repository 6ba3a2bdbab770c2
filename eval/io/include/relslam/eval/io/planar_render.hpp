#pragma once
// A picture of one iteration of a planar run (thesis Chapter 4), the top-down overlay of
// the thesis's screenshots (Fig. 67): true walls (yellow), mapped planes (blue), the planes seen now
// placed at the estimated pose (red, the thesis's "current readings"), each group's label at its
// position with thin lines to its member planes (as thesis Fig. 67 / paper Fig. 2), the true
// (orange) and estimated (blue) paths and the frustum at the estimated pose. Plain data in, an
// image out, like map_render.hpp: the scene is filled by the planar replay.

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"
#include "relslam/eval/io/render_frame.hpp"
#include "relslam/sim/viewing_frustum.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace cv {
class Mat;
}

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

// The picture's axes for a planar run: world x right, z up (the top view; RenderView::Side
// has no meaning in a 2½D world and is not drawn). The frames of map_render.hpp, with
// center_u, center_v = x, z.
RenderFrame fit_everything(const PlanarScene& scene, const RenderOptions& options);
// Around the robot (true, else estimated) and its frustum.
RenderFrame fit_robot(const PlanarScene& scene, const RenderOptions& options);

// The picture (BGR, options.width x options.height). options.labels: the group labels (auto:
// when at most auto_label_limit groups are in the picture).
cv::Mat render_map(const PlanarScene& scene, const RenderFrame& frame, const RenderOptions& options);

}  // namespace relslam::eval
