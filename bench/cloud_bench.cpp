// Plane extraction on sensor-sized point clouds, per extractor (em2, em1, the Open3D baseline,
// raw SegmentPlane): ms per frame (thread CPU time, one core; the median of --repeat runs for
// EM, one run for the Open3D extractors), planes found, and on synthetic frames recall,
// precision and the largest normal error against the truth. Frames: a 640 × 480 room (walls,
// floor, ceiling, a pillar) rendered noise-free and at a Kinect-like noise (σ = 0.0012 z², 5 %
// missing returns), the real Kinect frame and Velodyne VLP-16 scan of Debian's mrpt-common
// (skipped where absent). Nothing is asserted: the numbers are read.
//
//   relslam_bench_clouds [--repeat N] [--no-segment-plane]
#include "relslam/eval/sources/cloud_planes.hpp"

#include "depth_scenes.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace relslam;

struct Case {
  std::string name;
  eval::PointCloudFrame frame;
  std::optional<em::test::DepthScene> scene;
  std::optional<em::test::DepthFrame> truth;
  eval::CloudPlaneOptions options;
};

Case synthetic(const std::string& name, double noise_k, double missing) {
  Case c;
  c.name = name;
  c.scene = em::test::box_room(0.3, true);
  c.truth = em::test::render(*c.scene, noise_k, missing, 1);
  c.frame.points = c.truth->points;
  c.frame.width = c.scene->width, c.frame.height = c.scene->height;
  c.frame.source = "synthetic";
  return c;
}

std::optional<Case> from_rawlog(const std::string& name, const std::filesystem::path& file, double inlier_distance,
                                int summary_points) {
  if (!std::filesystem::exists(file)) {
    std::printf("%-22s skipped: %s not found (Debian package mrpt-common)\n", name.c_str(), file.c_str());
    return std::nullopt;
  }
  Case c;
  c.name = name;
  c.frame = eval::read_point_cloud_rawlog(file).frames.front();
  c.options.em = em::EmOptions::for_point_sigma(inlier_distance / 3.0);
  c.options.em.inlier_distance = inlier_distance;
  c.options.dense.summary_points = summary_points;
  return c;
}

void run(const Case& c, eval::CloudExtractor e, int repeat) {
  std::vector<double> ms;
  eval::CloudPlanes found;
  const bool open3d = e == eval::CloudExtractor::RansacOpen3d || e == eval::CloudExtractor::SegmentPlane;
  for (int k = 0; k < (open3d ? 1 : repeat); ++k) {
    found = eval::extract_cloud_planes(e, c.frame, c.options, 1);
    ms.push_back(found.ms);
  }
  std::sort(ms.begin(), ms.end());
  std::printf("%-22s %-14s %8zu %8d %9.1f %7zu", c.name.c_str(), std::string(eval::to_string(e)).c_str(),
              c.frame.returns(), found.summary_points, ms[ms.size() / 2], found.result.planes.size());
  if (c.truth) {
    std::vector<std::vector<int>> supports;
    std::vector<Eigen::Vector3d> normals;
    for (const em::EmPlane& p : found.result.planes) supports.push_back(p.points), normals.push_back(p.normal);
    const em::test::DepthScore s = em::test::score(*c.scene, *c.truth, supports, normals, 2000);
    std::printf(" %7.2f %9.2f %11.4f %5d", s.recall(), s.precision(), s.max_normal_error_deg, s.duplicates);
  }
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 5;
  bool segment_plane = true;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
    if (!std::strcmp(argv[i], "--no-segment-plane")) segment_plane = false;
  }
  std::vector<Case> cases;
  cases.push_back(synthetic("room 640x480 exact", 0.0, 0.0));
  cases.push_back(synthetic("room 640x480 kinect", 0.0012, 0.05));
  if (auto c = from_rawlog("kinect tests_rgbd", "/usr/share/mrpt/datasets/tests_rgbd.rawlog", 0.05, 4800))
    cases.push_back(*c);
  if (auto c = from_rawlog("velodyne VLP16", "/usr/share/mrpt/datasets/test_velodyne_VLP16.rawlog", 0.1, 20000))
    cases.push_back(*c);
  std::printf("%-22s %-14s %8s %8s %9s %7s %7s %9s %11s %5s\n", "frame", "extractor", "points", "summary", "ms",
              "planes", "recall", "precision", "normal_deg", "dups");
  for (const Case& c : cases)
    for (eval::CloudExtractor e : eval::kCloudExtractors) {
      if (!eval::cloud_extractor_available(e) || (e == eval::CloudExtractor::SegmentPlane && !segment_plane)) continue;
      run(c, e, repeat);
    }
  return 0;
}
