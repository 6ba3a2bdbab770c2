#include "relslam/eval/io/map_render.hpp"

#include "render_drawing.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace relslam::eval {
namespace {

using render::draw_text;
using render::group_colour;

// Colours (BGR), after the thesis's renders: green RltPoint boxes, black final and red
// temporary labels (Fig 127), true robot blue and estimated robot red (Figs 153–156).
const cv::Scalar kTruePoint(170, 170, 170);
const cv::Scalar kTrueDynamic(0, 140, 255);
const cv::Scalar kPointBox(0, 160, 0);
const cv::Scalar kFinalLabel(0, 0, 0);
const cv::Scalar kTemporaryLabel(0, 0, 220);
const cv::Scalar kDynamicMark(200, 0, 200);
const cv::Scalar kTrueRobot(220, 80, 0);
const cv::Scalar kEstimatedRobot(0, 0, 230);

// The picture's two world axes for a view.
Eigen::Vector2d plane(const Eigen::Vector3d& p, RenderView view) {
  return view == RenderView::Top ? Eigen::Vector2d(p.z(), p.x()) : Eigen::Vector2d(p.z(), p.y());
}

// World points to pixels through the view's two axes.
class Projection {
 public:
  Projection(const RenderFrame& frame, const RenderOptions& options) : map_(frame, options), view_(options.view) {}
  cv::Point operator()(const Eigen::Vector3d& p) const { return map_.pixel(plane(p, view_)); }
  bool inside(const cv::Point& px, int w, int h) const { return render::PixelMap::inside(px, w, h); }

 private:
  render::PixelMap map_;
  RenderView view_;
};

void draw_path(cv::Mat& image, const std::vector<Eigen::Vector3d>& path, const Projection& project,
               const cv::Scalar& colour) {
  std::vector<cv::Point> px;
  px.reserve(path.size());
  for (const Eigen::Vector3d& p : path) px.push_back(project(p));
  if (px.size() >= 2) cv::polylines(image, px, false, colour, 1, cv::LINE_AA);
}

// The robot as a triangle pointing along its +z, and (top view) its frustum as a wedge.
void draw_robot(cv::Mat& image, const Rigid3& pose, const SceneFrustum& frustum, const Projection& project,
                RenderView view, const cv::Scalar& colour, bool filled) {
  const double size = std::max(2.0, 0.03 * frustum.far);
  const std::vector<cv::Point> body = {project(pose * Eigen::Vector3d(0, 0, size)),
                                       project(pose * Eigen::Vector3d(0.5 * size, 0, -0.5 * size)),
                                       project(pose * Eigen::Vector3d(-0.5 * size, 0, -0.5 * size))};
  if (filled) {
    cv::fillConvexPoly(image, body, colour, cv::LINE_AA);
  } else {
    cv::polylines(image, body, true, colour, 2, cv::LINE_AA);
  }
  // The far end is a plane z = far (sim.frustum), so the wedge's sides are far / cos(angle) long.
  const double t = std::tan(frustum.half_angle_rad);
  std::vector<cv::Point> wedge;
  if (view == RenderView::Top) {
    wedge = {project(pose * Eigen::Vector3d(frustum.near * t, 0, frustum.near)),
             project(pose * Eigen::Vector3d(frustum.far * t, 0, frustum.far)),
             project(pose * Eigen::Vector3d(-frustum.far * t, 0, frustum.far)),
             project(pose * Eigen::Vector3d(-frustum.near * t, 0, frustum.near))};
  } else {
    wedge = {project(pose * Eigen::Vector3d(0, 0, frustum.near)), project(pose * Eigen::Vector3d(0, 0, frustum.far))};
  }
  cv::polylines(image, wedge, view == RenderView::Top, colour, 1, cv::LINE_AA);
}

std::vector<render::LegendEntry> legend(bool has_groups) {
  std::vector<render::LegendEntry> entries = {{"true point", kTruePoint},
                                              {"true dynamic point", kTrueDynamic},
                                              {"map point (RltPoint / EKF landmark)", kPointBox},
                                              {"flagged dynamic", kDynamicMark},
                                              {"true robot and frustum", kTrueRobot},
                                              {"estimated robot and frustum", kEstimatedRobot}};
  if (has_groups) {
    entries.push_back({"label: final group (black)", kFinalLabel});
    entries.push_back({"label: temporary group (red)", kTemporaryLabel});
  }
  return entries;
}

}  // namespace

RenderFrame fit_everything(const RenderScene& scene, const RenderOptions& options) {
  render::FitBox box;
  auto grow = [&](const Eigen::Vector3d& p) { box.grow(plane(p, options.view)); };
  for (const auto& p : scene.true_points) grow(p);
  for (const auto& p : scene.true_path) grow(p);
  for (const auto& p : scene.estimated_path) grow(p);
  for (const auto& l : scene.landmarks) grow(l.p);
  return box.fit(options);
}

RenderFrame fit_robot(const RenderScene& scene, const RenderOptions& options) {
  const std::optional<Rigid3>& pose = scene.true_pose ? scene.true_pose : scene.estimated_pose;
  // A close-up (thesis Fig 129): the robot and the near part of what it sees [C].
  const Eigen::Vector3d centre =
      pose ? Eigen::Vector3d(*pose * Eigen::Vector3d(0, 0, 0.25 * scene.frustum.far)) : Eigen::Vector3d::Zero();
  const Eigen::Vector2d uv = plane(centre, options.view);
  return {uv.x(), uv.y(), 0.8 * scene.frustum.far};
}

namespace {

// The scene itself: true points and paths, the map with its groups, the robots.
void draw_scene(cv::Mat& image, const RenderScene& scene, const RenderFrame& frame, const RenderOptions& options) {
  const Projection project(frame, options);
  const int w = options.width, h = options.height;

  for (std::size_t i = 0; i < scene.true_points.size(); ++i) {
    const bool dynamic = i < scene.true_dynamic.size() && scene.true_dynamic[i];
    cv::circle(image, project(scene.true_points[i]), dynamic ? 3 : 1, dynamic ? kTrueDynamic : kTruePoint, cv::FILLED);
  }
  draw_path(image, scene.true_path, project, kTrueRobot);
  draw_path(image, scene.estimated_path, project, kEstimatedRobot);

  // Each point to its group's centroid, in the group's colour (thesis Fig 127).
  std::vector<const SceneGroup*> group_of_id;
  for (const SceneGroup& g : scene.groups) {
    if (g.id >= static_cast<int>(group_of_id.size())) group_of_id.resize(g.id + 1, nullptr);
    group_of_id[g.id] = &g;
  }
  int in_view = 0;
  for (const SceneLandmark& l : scene.landmarks) in_view += project.inside(project(l.p), w, h);
  const bool labels = options.labels.value_or(in_view <= options.auto_label_limit);
  for (const SceneLandmark& l : scene.landmarks)
    if (l.group >= 0 && l.group < static_cast<int>(group_of_id.size()) && group_of_id[l.group])
      cv::line(image, project(l.p), project(group_of_id[l.group]->centroid), group_colour(l.group), 1, cv::LINE_AA);
  for (const SceneLandmark& l : scene.landmarks) {
    const cv::Point px = project(l.p);
    if (l.dynamic) {
      cv::drawMarker(image, px, kDynamicMark, cv::MARKER_TILTED_CROSS, 9, 2);
    } else {
      cv::rectangle(image, {px.x - 2, px.y - 2}, {px.x + 2, px.y + 2}, kPointBox, 1);
    }
    if (labels)
      draw_text(image, std::to_string(l.id), {px.x + 4, px.y - 3},
                l.dynamic ? kDynamicMark
                : l.final ? kFinalLabel
                          : kTemporaryLabel,
                0.33);
  }
  if (labels)
    for (const SceneGroup& g : scene.groups)
      draw_text(image, "G" + std::to_string(g.id), project(g.centroid), g.final ? kFinalLabel : kTemporaryLabel, 0.35);

  // The true robot last: where the estimate is right, it stays visible on top.
  if (scene.estimated_pose)
    draw_robot(image, *scene.estimated_pose, scene.frustum, project, options.view, kEstimatedRobot, true);
  if (scene.true_pose) draw_robot(image, *scene.true_pose, scene.frustum, project, options.view, kTrueRobot, false);
}

}  // namespace

cv::Mat render_map(const RenderScene& scene, const RenderFrame& frame, const RenderOptions& options) {
  const render::PictureText text{
      scene.title, options.view == RenderView::Top ? "top view: z right, x up" : "side view: z right, y up",
      legend(!scene.groups.empty())};
  return render::draw_picture(frame, options, text,
                              [&](cv::Mat& image) { draw_scene(image, scene, frame, options); });
}

}  // namespace relslam::eval
