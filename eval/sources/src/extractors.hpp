#pragma once
// Internal to the sources layer: the extractor implementations plane_extractor.cpp lists.

#include "relslam/eval/io/point_cloud_rawlog.hpp"
#include "relslam/eval/sources/plane_extractor.hpp"

#include <span>

namespace relslam::eval {

struct SegmentPlaneOptions;  // cloud_planes.hpp

// EM algorithm 2 (incremental) or 1 (batch), libslam's run_em2 / run_em1.
std::unique_ptr<PlaneExtractor> make_em_extractor(PlaneExtractorKind kind, const ExtractorSettings& settings);
// The Open3D baseline (ransac_open3d_extractor.cpp, built only with Open3D).
std::unique_ptr<PlaneExtractor> make_ransac_open3d_extractor(const ExtractorSettings& settings);
// Its planes of any points (no rectangles), and raw SegmentPlane repeated (cloud_planes.hpp).
em::EmResult ransac_open3d_planes(std::span<const Eigen::Vector3d> points, const ExtractorSettings& settings,
                                  std::uint64_t seed);
em::EmResult segment_plane_planes(std::span<const Eigen::Vector3d> points, const SegmentPlaneOptions& options,
                                  std::uint64_t seed);
// A PLY or PCD file's points (Open3D's reader), each finite and within reach, else InputError.
PointCloudFrame read_open3d_points(const std::filesystem::path& path);

}  // namespace relslam::eval
