// Plane extraction on sensor-sized point clouds, per extractor (em2, em1, the Open3D baseline,
// raw SegmentPlane): ms per frame (thread CPU time, one core; the median of --repeat runs for
// EM, one run for the Open3D extractors), planes found, and on synthetic frames recall,
// precision and the largest normal error against the truth. Frames: a 640 × 480 room (walls,
// floor, ceiling, a pillar) rendered noise-free and at a Kinect-like noise (σ = 0.0012 z², 5 %
// missing returns), the real Kinect frame and Velodyne VLP-16 scan of Debian's mrpt-common
// (skipped where absent); and frames of the simulated depth camera (sim/depth_camera.hpp) over
// planar worlds with floor and ceiling, noise-free and at the Kinect's noise: a room with a
// pillar from six poses, and Map E (e_motion_room) every 60th pose of its path, scored over all
// frames of a set (recall over the surfaces with at least 0.5 square units in view). Nothing is
// asserted: the numbers are read.
//
//   relslam_bench_clouds [--repeat N] [--no-segment-plane]
#include "relslam/eval/sources/cloud_planes.hpp"

#include "depth_scenes.hpp"
#include "relslam/eval/io/planar_map_file.hpp"
#include "relslam/sim/planar_path.hpp"
#include "sim_depth_views.hpp"

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

// A set of simulated depth frames through one extractor: the median ms per frame, the planes,
// and recall / precision / largest normal error over all frames.
void run_views(const std::string& name, const sim::PlanarWorld& world, const std::vector<PlanarPose>& poses,
               const sim::DepthCameraOptions& camera, const eval::CloudPlaneOptions& options, eval::CloudExtractor e) {
  std::vector<double> ms;
  em::test::DepthScore total;
  long long points = 0, summary = 0;
  for (std::size_t k = 0; k < poses.size(); ++k) {
    const em::test::SimDepthView view = em::test::sim_depth_view(world, camera, poses[k], 1, static_cast<int>(k));
    eval::PointCloudFrame frame;
    frame.points = view.points;
    frame.width = view.width, frame.height = view.height;
    const eval::CloudPlanes found = eval::extract_cloud_planes(e, frame, options, 1);
    ms.push_back(found.ms);
    points += static_cast<long long>(frame.returns()), summary += found.summary_points;
    const em::test::DepthScore s = em::test::score_view(view, found.result.planes, 0.5);
    total.true_planes += s.true_planes, total.found += s.found, total.planes += s.planes;
    total.correct += s.correct, total.duplicates += s.duplicates;
    total.max_normal_error_deg = std::max(total.max_normal_error_deg, s.max_normal_error_deg);
  }
  std::sort(ms.begin(), ms.end());
  const auto n = static_cast<long long>(poses.size());
  std::printf("%-22s %-14s %8lld %8lld %9.1f %7.1f %7.3f %9.3f %11.4f %5d   (%d surfaces in %lld frames)\n",
              name.c_str(), std::string(eval::to_string(e)).c_str(), points / n, summary / n, ms[ms.size() / 2],
              static_cast<double>(total.planes) / static_cast<double>(n), total.recall(), total.precision(),
              total.max_normal_error_deg, total.duplicates, total.true_planes, n);
}

struct ViewSet {
  std::string name;
  sim::PlanarWorld world;
  std::vector<PlanarPose> poses;
  sim::DepthCameraOptions camera;
  eval::CloudPlaneOptions options;
};

std::vector<ViewSet> view_sets() {
  sim::DepthCameraOptions exact, kinect;  // kinect: the camera's defaults
  exact.noise_per_depth2 = 0.0, exact.missing = 0.0;
  const eval::CloudPlaneOptions defaults;
  std::vector<ViewSet> sets = {
      {"sim pillar room exact", em::test::pillar_room(), em::test::pillar_room_poses(), exact, defaults},
      {"sim pillar room kinect", em::test::pillar_room(), em::test::pillar_room_poses(), kinect, defaults}};
  const sim::PlanarMap map = eval::read_planar_map(RELSLAM_SOURCE_DIR "/scenarios/maps/e_motion_room.json");
  const sim::PlanarPath path(map.path);
  std::vector<PlanarPose> poses;
  for (int k = 0; k < path.iterations(); k += 60) poses.push_back(path.world_T_robot(k));
  sets.push_back({"sim map E exact", map.world, poses, exact, defaults});
  sets.push_back({"sim map E kinect", map.world, poses, kinect, defaults});
  // d_in growing as the camera's 3σ (EmOptions::inlier_per_range2), as the depth scenarios use it.
  eval::CloudPlaneOptions grows;
  grows.em.inlier_per_range2 = 3.0 * kinect.noise_per_depth2;
  sets.push_back({"sim map E kinect d(r)", map.world, poses, kinect, grows});
  return sets;
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
  auto wanted = [&](eval::CloudExtractor e) {
    return eval::cloud_extractor_available(e) && (e != eval::CloudExtractor::SegmentPlane || segment_plane);
  };
  for (const Case& c : cases)
    for (eval::CloudExtractor e : eval::kCloudExtractors)
      if (wanted(e)) run(c, e, repeat);
  for (const ViewSet& v : view_sets())
    for (eval::CloudExtractor e : eval::kCloudExtractors)
      if (wanted(e) && (e != eval::CloudExtractor::SegmentPlane || v.poses.size() <= 6)) run_views(v.name, v.world, v.poses, v.camera, v.options, e);
  return 0;
}
