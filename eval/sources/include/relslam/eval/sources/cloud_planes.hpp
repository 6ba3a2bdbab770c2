#pragma once
// Planes from a sensor's point cloud (a depth frame, a lidar scan, a point file) by each
// extractor relslam compares: EM2 and EM1 at sensor density (libslam's dense extraction), the
// Open3D baseline of the planar scenarios on the same summary and densified the same way, and
// Open3D's SegmentPlane alone on every point, as a practitioner would call it.

#include "relslam/em/dense_extraction.hpp"
#include "relslam/eval/config/extraction_options.hpp"
#include "relslam/eval/io/point_cloud_rawlog.hpp"

#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

namespace relslam::eval {

enum class CloudExtractor : unsigned char { Em2, Em1, RansacOpen3d, SegmentPlane };
constexpr CloudExtractor kCloudExtractors[] = {CloudExtractor::Em2, CloudExtractor::Em1, CloudExtractor::RansacOpen3d,
                                               CloudExtractor::SegmentPlane};
std::string_view to_string(CloudExtractor e);  // "em2", "em1", "ransac_open3d", "segment_plane"
bool cloud_extractor_available(CloudExtractor e);  // the Open3D ones need an Open3D build

// SegmentPlane repeated on the points left until it finds fewer than min_inliers: the
// practitioner's default (the values of Open3D's tutorial scaled to a room: 2 cm, 1000
// iterations) [C].
struct SegmentPlaneOptions {
  double distance = 0.02;  // units (m)
  int iterations = 1000;
  int min_inliers = 2000;
  int max_planes = 10;
};

struct CloudPlaneOptions {
  em::EmOptions em = em::EmOptions::for_point_sigma(0.01);  // d_in 5 cm: 3σ of a Kinect at 3.5 m [C]
  em::DenseOptions dense;
  RansacOptions ransac;  // the baseline's (its threshold 0: EM's d_in)
  SegmentPlaneOptions segment_plane;
};

struct CloudPlanes {
  em::EmResult result;  // planes over the frame's point indices, rectangles set
  int summary_points = 0;  // what the extractor ran on (segment_plane: every point)
  double ms = 0;           // thread CPU time of the extraction
};

// One frame through one extractor, seeded by `seed`. Throws std::invalid_argument for an
// extractor this build does not have.
CloudPlanes extract_cloud_planes(CloudExtractor extractor, const PointCloudFrame& frame,
                                 const CloudPlaneOptions& options, std::uint64_t seed);

// A plain point file as one unorganised frame: CSV (a header, then x,y,z per row, relslam's
// axes) always; PLY and PCD through Open3D when relslam was built with it. Throws InputError
// (file, line, field) for a missing or unreadable file, a non-finite or out-of-reach
// coordinate, or no point at all.
PointCloudFrame read_point_file(const std::filesystem::path& path);

}  // namespace relslam::eval
