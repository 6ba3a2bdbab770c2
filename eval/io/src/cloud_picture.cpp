#include "relslam/eval/io/cloud_picture.hpp"

#include "relslam/eval/io/image_file.hpp"

#include <opencv2/core.hpp>

#include <algorithm>
#include <array>
#include <limits>

namespace relslam::eval {
namespace {

// Twelve well-separated colours (BGR), repeated beyond.
cv::Vec3b colour(int plane) {
  static constexpr std::array<std::array<unsigned char, 3>, 12> kPalette = {{{60, 76, 231},
                                                                            {113, 204, 46},
                                                                            {219, 152, 52},
                                                                            {15, 196, 241},
                                                                            {182, 89, 155},
                                                                            {34, 126, 230},
                                                                            {156, 188, 26},
                                                                            {94, 73, 52},
                                                                            {133, 193, 255},
                                                                            {255, 128, 128},
                                                                            {0, 128, 128},
                                                                            {128, 0, 255}}};
  if (plane < 0) return {128, 128, 128};
  const auto& c = kPalette[static_cast<std::size_t>(plane) % kPalette.size()];
  return {c[0], c[1], c[2]};
}

cv::Mat image_view(const PointCloudFrame& frame, const std::vector<int>& plane_of) {
  cv::Mat image(frame.height, frame.width, CV_8UC3, cv::Scalar(0, 0, 0));
  for (int r = 0; r < frame.height; ++r)
    for (int c = 0; c < frame.width; ++c) {
      const auto i = static_cast<std::size_t>(r) * static_cast<std::size_t>(frame.width) + static_cast<std::size_t>(c);
      if (frame.points[i].allFinite()) image.at<cv::Vec3b>(r, c) = colour(plane_of[i]);
    }
  return image;
}

cv::Mat top_view(const PointCloudFrame& frame, const std::vector<int>& plane_of) {
  constexpr int kSide = 800;
  double lo_x = std::numeric_limits<double>::infinity(), hi_x = -lo_x, lo_z = lo_x, hi_z = -lo_x;
  for (const Eigen::Vector3d& p : frame.points) {
    if (!p.allFinite()) continue;
    lo_x = std::min(lo_x, p.x()), hi_x = std::max(hi_x, p.x());
    lo_z = std::min(lo_z, p.z()), hi_z = std::max(hi_z, p.z());
  }
  cv::Mat image(kSide, kSide, CV_8UC3, cv::Scalar(0, 0, 0));
  const double span = std::max({hi_x - lo_x, hi_z - lo_z, 1e-9});
  const double scale = (kSide - 1) / span;
  // Unassigned points first, so planes are drawn over them.
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t i = 0; i < frame.points.size(); ++i) {
      const Eigen::Vector3d& p = frame.points[i];
      if (!p.allFinite() || (plane_of[i] >= 0) != (pass == 1)) continue;
      const int column = static_cast<int>((hi_x - p.x()) * scale), row = static_cast<int>((hi_z - p.z()) * scale);
      if (column >= 0 && column < kSide && row >= 0 && row < kSide) image.at<cv::Vec3b>(row, column) = colour(plane_of[i]);
    }
  return image;
}

}  // namespace

void write_cloud_picture(const std::string& file, const PointCloudFrame& frame, const std::vector<int>& plane_of) {
  write_image(file, frame.organised() ? image_view(frame, plane_of) : top_view(frame, plane_of));
}

}  // namespace relslam::eval
