#pragma once
// `relslam extract`: planes from real point clouds (a rawlog of depth frames or lidar scans, or
// a point file) by every plane extractor, into CSV tables and pictures.

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace relslam::eval {

struct ExtractArgs {
  std::string rawlog;  // an MRPT rawlog of clouds, or
  std::string points;  // a point file (.csv, .ply, .pcd)
  std::string out;
  bool force = false;
  std::vector<std::string> extractors{"em2", "em1", "ransac_open3d", "segment_plane"};
  std::uint64_t seed = 1;
  int max_frames = 0;  // 0: all
  double inlier_distance = 0.05;
  double inlier_per_range2 = 0.0;
  double seed_radius_per_range = 0.0;
  int summary_points = 4800;
  bool pictures = true;
  bool quiet = false;
};

void add_extract(CLI::App& app, ExtractArgs& args);
int run_extract(const ExtractArgs& args);

}  // namespace relslam::eval
