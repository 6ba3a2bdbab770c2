#pragma once
// A picture of one iteration of a run, like thesis Figures 127–129 (the Relative map: RltPoints
// and the groups that map them) and 153–162 (estimated against true robot): plain data in, an
// image out. The scene (render_scene.hpp) is filled by the replay (point_replay.hpp); drawing
// knows nothing of runs.

#include "relslam/eval/io/render_frame.hpp"
#include "relslam/eval/io/render_scene.hpp"

namespace cv {
class Mat;
}

namespace relslam::eval {

// The frame that shows every true point and both paths, with a margin.
RenderFrame fit_everything(const RenderScene& scene, const RenderOptions& options);
// The frame around the true (else estimated) robot that holds its frustum.
RenderFrame fit_robot(const RenderScene& scene, const RenderOptions& options);

// The picture (BGR, options.width x options.height).
cv::Mat render_map(const RenderScene& scene, const RenderFrame& frame, const RenderOptions& options);

}  // namespace relslam::eval
