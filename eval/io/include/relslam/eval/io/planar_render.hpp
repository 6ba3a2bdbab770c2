#pragma once
// A picture of one iteration of a planar run (thesis Chapter 4), the top-down overlay of
// the thesis's screenshots (Fig. 67): true walls (yellow), mapped planes (blue), the planes seen now
// placed at the estimated pose (red, the thesis's "current readings"), each group's label at its
// position with thin lines to its member planes (as thesis Fig. 67 / paper Fig. 2), the true
// (orange) and estimated (blue) paths and the frustum at the estimated pose. Plain data in, an
// image out, like map_render.hpp: the scene (planar_scene.hpp) is filled by the planar replay.

#include "relslam/eval/io/planar_scene.hpp"
#include "relslam/eval/io/render_frame.hpp"

namespace cv {
class Mat;
}

namespace relslam::eval {

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
