#include "render_drawing.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace relslam::eval::render {

PixelMap::PixelMap(const RenderFrame& frame, const RenderOptions& options)
    : frame_(frame),
      scale_(std::max(options.width, options.height) / frame.span),
      half_w_(options.width / 2.0),
      half_h_(options.height / 2.0) {}

cv::Point PixelMap::pixel(const Eigen::Vector2d& uv) const {
  return {static_cast<int>(std::lround(half_w_ + (uv.x() - frame_.center_u) * scale_)),
          static_cast<int>(std::lround(half_h_ - (uv.y() - frame_.center_v) * scale_))};
}

cv::Scalar group_colour(int id) {
  const double hue = std::fmod(0.618033988749895 * id, 1.0) * 180.0;
  cv::Mat hsv(1, 1, CV_8UC3, cv::Scalar(hue, 200, 190)), bgr;
  cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
  const cv::Vec3b c = bgr.at<cv::Vec3b>(0, 0);
  return {static_cast<double>(c[0]), static_cast<double>(c[1]), static_cast<double>(c[2])};
}

void draw_text(cv::Mat& image, const std::string& text, cv::Point at, const cv::Scalar& colour, double size) {
  cv::putText(image, text, at, cv::FONT_HERSHEY_SIMPLEX, size, colour, 1, cv::LINE_AA);
}

void draw_scale_bar(cv::Mat& image, const RenderFrame& frame, const RenderOptions& options) {
  const double pixels_per_unit = std::max(options.width, options.height) / frame.span;
  // The largest of 1, 2, 5 x 10^n that fits in a fifth of the picture.
  double length = std::pow(10.0, std::floor(std::log10(0.2 * frame.span)));
  for (double m : {5.0, 2.0})
    if (m * length * pixels_per_unit <= 0.2 * options.width) {
      length *= m;
      break;
    }
  const int px = static_cast<int>(std::lround(length * pixels_per_unit));
  const cv::Point a(12, options.height - 14), b(12 + px, options.height - 14);
  cv::line(image, a, b, kText, 2);
  char text[32];
  std::snprintf(text, sizeof text, "%g units", length);
  draw_text(image, text, {12, options.height - 20}, kText);
}

namespace {

// Pixels of `box` that differ from the picture's background (its top-left pixel): how much of the
// drawing a legend there would cover.
int drawn_pixels(const cv::Mat& image, const cv::Rect& box) {
  const cv::Vec3b background = image.at<cv::Vec3b>(0, 0);
  int n = 0;
  for (int r = box.y; r < box.y + box.height; ++r)
    for (int c = box.x; c < box.x + box.width; ++c) n += image.at<cv::Vec3b>(r, c) != background;
  return n;
}

}  // namespace

void draw_legend(cv::Mat& image, const std::vector<LegendEntry>& entries) {
  const int line = 16, width = 290 + 4;
  const int height = line * static_cast<int>(entries.size()) + 14;
  const int x = image.cols - width + 8;
  if (x < 8 || height + 8 > image.rows) return;  // no room beside the drawing
  // The right edge's lower or upper corner, whichever covers less of what is drawn.
  const cv::Rect lower(x - 8, image.rows - height - 4, width, height), upper(x - 8, 4, width, height);
  const cv::Rect box = drawn_pixels(image, upper) < drawn_pixels(image, lower) ? upper : lower;
  cv::rectangle(image, box, {245, 245, 245}, cv::FILLED);
  int y = box.y + 14;
  for (const LegendEntry& e : entries) {
    cv::rectangle(image, {x, y - 8}, {x + 8, y}, e.colour, cv::FILLED);
    draw_text(image, e.text, {x + 14, y}, kText);
    y += line;
  }
}

RenderFrame fit_box(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, const RenderOptions& options) {
  if (!(lo.array() <= hi.array()).all()) return {};
  const Eigen::Vector2d c = 0.5 * (lo + hi), extent = hi - lo;
  // The wider picture side takes the span; the other side must still hold its extent.
  const double aspect =
      static_cast<double>(std::max(options.width, options.height)) / std::min(options.width, options.height);
  const bool wide = options.width >= options.height;
  const double span = std::max(wide ? extent.x() : extent.y(), (wide ? extent.y() : extent.x()) * aspect);
  return {c.x(), c.y(), 1.08 * std::max(span, 1.0)};
}

cv::Mat draw_picture(const RenderFrame& frame, const RenderOptions& options, const PictureText& text,
                     const std::function<void(cv::Mat&)>& draw) {
  cv::Mat image(options.height, options.width, CV_8UC3, cv::Scalar(255, 255, 255));
  draw(image);
  draw_text(image, text.title, {12, 22}, kText, 0.55);
  draw_text(image, text.axes, {12, 42}, kText);
  draw_scale_bar(image, frame, options);
  draw_legend(image, text.legend);
  return image;
}

}  // namespace relslam::eval::render
