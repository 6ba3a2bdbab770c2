#pragma once
// Internal to io: what the point picture (map_render.cpp) and the planar picture
// (planar_render.cpp) draw alike — the picture skeleton both are drawn through, world-to-pixel
// mapping, text, the scale bar, the legend, the fit rule and the group colours — so both kinds
// of run look like one family of figures.

#include "relslam/eval/io/render_frame.hpp"

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace relslam::eval::render {

// World (u, v) to pixels: u to the right, v up.
class PixelMap {
 public:
  PixelMap(const RenderFrame& frame, const RenderOptions& options);
  cv::Point pixel(const Eigen::Vector2d& uv) const;
  static bool inside(const cv::Point& px, int w, int h) { return px.x >= 0 && px.y >= 0 && px.x < w && px.y < h; }

 private:
  RenderFrame frame_;
  double scale_, half_w_, half_h_;
};

// A stable, well-spread colour per group (golden-ratio hue steps), so a group keeps its colour
// from frame to frame of a video.
cv::Scalar group_colour(int id);

inline const cv::Scalar kText(40, 40, 40);

void draw_text(cv::Mat& image, const std::string& text, cv::Point at, const cv::Scalar& colour, double size = 0.4);
void draw_scale_bar(cv::Mat& image, const RenderFrame& frame, const RenderOptions& options);

struct LegendEntry {
  std::string text;
  cv::Scalar colour;
};
// A box of colour swatches at the right edge, in the lower or the upper corner, whichever covers
// less of the drawing.
void draw_legend(cv::Mat& image, const std::vector<LegendEntry>& entries);

// The frame that holds the box lo..hi (picture axes u, v) with a margin, the wider picture side
// taking the span.
RenderFrame fit_box(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, const RenderOptions& options);

// The box around everything a picture must hold (picture axes u, v), grown point by point, then
// fitted as fit_box: the fit-everything rule of both kinds of picture.
class FitBox {
 public:
  void grow(const Eigen::Vector2d& uv) {
    lo_ = lo_.cwiseMin(uv);
    hi_ = hi_.cwiseMax(uv);
  }
  RenderFrame fit(const RenderOptions& options) const { return fit_box(lo_, hi_, options); }

 private:
  Eigen::Vector2d lo_ = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi_ = -lo_;
};

// What every picture carries over its drawing, in the same places: the title, the view's axes
// (top left), the scale bar and the legend.
struct PictureText {
  std::string title;
  std::string axes;  // "top view: z right, x up"
  std::vector<LegendEntry> legend;
};

// The one picture skeleton: a white picture (options.width x options.height, BGR), the run's
// own drawing, then `text` over it.
cv::Mat draw_picture(const RenderFrame& frame, const RenderOptions& options, const PictureText& text,
                     const std::function<void(cv::Mat&)>& draw);

}  // namespace relslam::eval::render
