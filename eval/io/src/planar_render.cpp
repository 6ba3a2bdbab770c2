#include "relslam/eval/io/planar_render.hpp"

#include "render_drawing.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace relslam::eval {
namespace {

using render::draw_text;
using render::PixelMap;

// Colours (BGR) after the thesis's screenshots (Fig. 67, paper Fig. 2): true
// walls yellow, mapped planes blue, current readings red; true path orange, estimated blue.
const cv::Scalar kWall(0, 215, 255);
const cv::Scalar kMappedPlane(200, 70, 0);
const cv::Scalar kReading(0, 0, 230);
const cv::Scalar kTruePath(0, 140, 255);
const cv::Scalar kEstimatedPath(230, 150, 60);
const cv::Scalar kGroupLabel(0, 0, 0);

// A group's lines: its own colour (stable over a video) dimmed halfway to grey, so that a red
// or blue group cannot pass for readings or mapped planes [C].
cv::Scalar group_line_colour(int id) { return 0.5 * render::group_colour(id) + cv::Scalar(50, 50, 50); }

// Walls are drawn wider than the planes on them, so where the map is right (noise-free runs)
// the yellow still shows around the blue [C].
int wall_width(int picture) { return std::max(3, picture / 240); }
int plane_width(int picture) { return std::max(1, picture / 640); }

void draw_segments(cv::Mat& image, const std::vector<PlaneObject>& planes, const PixelMap& map,
                   const cv::Scalar& colour, int width) {
  // No anti-aliasing: the planes keep their exact colour, which tests and readers can pick out.
  for (const PlaneObject& p : planes) cv::line(image, map.pixel(p.a), map.pixel(p.b), colour, width, cv::LINE_8);
}

void draw_path(cv::Mat& image, const std::vector<Eigen::Vector2d>& path, const PixelMap& map,
               const cv::Scalar& colour) {
  std::vector<cv::Point> px;
  px.reserve(path.size());
  for (const Eigen::Vector2d& p : path) px.push_back(map.pixel(p));
  if (px.size() >= 2) cv::polylines(image, px, false, colour, 1, cv::LINE_AA);
}

// The robot as a triangle pointing along its +x (its viewing direction).
void draw_robot(cv::Mat& image, const PlanarPose& pose, double size, const PixelMap& map, const cv::Scalar& colour,
                bool filled) {
  const std::vector<cv::Point> body = {map.pixel(pose * Eigen::Vector2d(size, 0)),
                                       map.pixel(pose * Eigen::Vector2d(-0.5 * size, 0.5 * size)),
                                       map.pixel(pose * Eigen::Vector2d(-0.5 * size, -0.5 * size))};
  if (filled) {
    cv::fillConvexPoly(image, body, colour, cv::LINE_AA);
  } else {
    cv::polylines(image, body, true, colour, 2, cv::LINE_AA);
  }
}

// The footprint of sim::ViewingFrustum in the robot frame: the thesis's trapezoid
// {near <= x <= far, |z| <= x tan α}, or the sector that replaces its far edge by an arc.
std::vector<Eigen::Vector2d> frustum_outline(const sim::ViewingFrustum& f) {
  const double t = std::tan(f.half_angle_rad);
  std::vector<Eigen::Vector2d> out = {{f.near, -f.near * t}};
  if (f.shape == sim::FrustumShape::Planar) {
    out.push_back({f.far, -f.far * t});
    out.push_back({f.far, f.far * t});
  } else {
    constexpr int kSteps = 24;
    for (int i = 0; i <= kSteps; ++i) {
      const double angle = -f.half_angle_rad + 2.0 * f.half_angle_rad * i / kSteps;
      out.push_back({f.far * std::cos(angle), f.far * std::sin(angle)});
    }
  }
  out.push_back({f.near, f.near * t});
  return out;
}

std::vector<render::LegendEntry> legend(const PlanarScene& scene) {
  std::vector<render::LegendEntry> entries = {{"true wall", kWall},
                                              {"mapped plane", kMappedPlane},
                                              {"current readings at the estimated pose", kReading},
                                              {"true path and robot", kTruePath},
                                              {"estimated path, robot and frustum", kEstimatedPath}};
  if (!scene.groups.empty()) entries.push_back({"group X<id>: lines to its planes", kGroupLabel});
  return entries;
}

}  // namespace

RenderFrame fit_everything(const PlanarScene& scene, const RenderOptions& options) {
  render::FitBox box;
  for (const auto* planes : {&scene.walls, &scene.mapped, &scene.readings})
    for (const PlaneObject& p : *planes) {
      box.grow(p.a);
      box.grow(p.b);
    }
  for (const auto& p : scene.true_path) box.grow(p);
  for (const auto& p : scene.estimated_path) box.grow(p);
  return box.fit(options);
}

RenderFrame fit_robot(const PlanarScene& scene, const RenderOptions& options) {
  const std::optional<PlanarPose>& pose = scene.true_pose ? scene.true_pose : scene.estimated_pose;
  // A close-up: the robot and what its frustum holds (without one, the small frustum's reach).
  const double far = scene.frustum ? scene.frustum->far : sim::ViewingFrustum::small().far;
  const Eigen::Vector2d centre =
      pose ? Eigen::Vector2d(*pose * Eigen::Vector2d(0.4 * far, 0)) : Eigen::Vector2d::Zero();
  const double aspect = static_cast<double>(std::max(options.width, options.height)) /
                        std::max(1, std::min(options.width, options.height));
  return {centre.x(), centre.y(), 1.3 * far * aspect};
}

namespace {

// The scene itself: walls, paths, the map with its groups, the readings, the robots.
void draw_scene(cv::Mat& image, const PlanarScene& scene, const RenderFrame& frame, const RenderOptions& options) {
  const PixelMap map(frame, options);
  const int picture = std::max(options.width, options.height);

  draw_segments(image, scene.walls, map, kWall, wall_width(picture));
  draw_path(image, scene.true_path, map, kTruePath);
  draw_path(image, scene.estimated_path, map, kEstimatedPath);
  draw_segments(image, scene.mapped, map, kMappedPlane, plane_width(picture) + 1);

  // Each group to the midpoints of its member planes, in the group's colour: thin, so that a
  // plane shared by two groups (the linking planes of Rules 8-9) shows both lines (thesis
  // Fig. 67, paper Fig. 2).
  int groups_in_view = 0;
  for (const PlanarSceneGroup& g : scene.groups) {
    const cv::Point at = map.pixel(g.position);
    groups_in_view += PixelMap::inside(at, options.width, options.height);
    for (const Eigen::Vector2d& m : g.member_midpoints)
      cv::line(image, at, map.pixel(m), group_line_colour(g.id), 1, cv::LINE_AA);
  }
  // The readings over the map: where the pose and the map are right, red lies on blue.
  draw_segments(image, scene.readings, map, kReading, plane_width(picture));

  const bool labels = options.labels.value_or(groups_in_view <= options.auto_label_limit);
  for (const PlanarSceneGroup& g : scene.groups) {
    const cv::Point at = map.pixel(g.position);
    cv::circle(image, at, 3, group_line_colour(g.id), cv::FILLED, cv::LINE_AA);
    if (labels) draw_text(image, "X" + std::to_string(g.id), {at.x + 5, at.y - 5}, kGroupLabel, 0.45);
  }

  const double robot_size = 0.015 * frame.span;
  if (scene.estimated_pose) {
    if (scene.frustum) {
      std::vector<cv::Point> outline;
      for (const Eigen::Vector2d& p : frustum_outline(*scene.frustum))
        outline.push_back(map.pixel(*scene.estimated_pose * p));
      cv::polylines(image, outline, true, kEstimatedPath, 1, cv::LINE_AA);
    }
    draw_robot(image, *scene.estimated_pose, robot_size, map, kEstimatedPath, true);
  }
  // The true robot last: where the estimate is right, it stays visible on top.
  if (scene.true_pose) draw_robot(image, *scene.true_pose, robot_size, map, kTruePath, false);
}

}  // namespace

cv::Mat render_map(const PlanarScene& scene, const RenderFrame& frame, const RenderOptions& options) {
  const render::PictureText text{scene.title, "top view: x right, z up", legend(scene)};
  return render::draw_picture(frame, options, text,
                              [&](cv::Mat& image) { draw_scene(image, scene, frame, options); });
}

}  // namespace relslam::eval
