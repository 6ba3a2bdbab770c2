// The baseline plane extractor: Open3D's RANSAC plane segmentation
// (PointCloud::SegmentPlane) repeated on the points left, each plane's inliers split into
// connected pieces by ClusterDBSCAN (RANSAC's plane is infinite: collinear walls and the far
// side of a gap would otherwise be one plane), each piece refit by TLS and converted by the same
// thesis 5.1 code as EM's planes. Seeded per frame through utility::random::Seed, and Open3D
// runs on one OpenMP thread like EM: SegmentPlane's threads draw from the one generator in
// whatever order they run, which made two runs differ, and on a shared machine the threads
// only slowed it down. Open3D stays inside this file. Also here: SegmentPlane alone, repeated on
// the points left (the practitioner's default the clouds' extraction compares against).
#include "extractors.hpp"

#include "relslam/eval/sources/cloud_planes.hpp"

#include "relslam/core/option_issue.hpp"
#include "relslam/em/em_plane.hpp"
#include "relslam/eval/config/input_error.hpp"

#include <open3d/geometry/PointCloud.h>
#include <open3d/io/PointCloudIO.h>
#include <open3d/utility/Logging.h>
#include <open3d/utility/Random.h>

#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <mutex>
#include <regex>
#include <span>

namespace relslam::eval {
namespace {

// Open3D prints its messages to stdout in colour, where relslam writes its CSV, JSON and
// progress. Once per process they go to stderr instead, without the colour codes, as relslam's
// own messages ("relslam: [Open3D WARNING] Read PCD failed: unable to read data."). Only errors
// by default; the reader lets warnings through, which say why a file could not be read.
void route_open3d_messages() {
  static std::once_flag once;
  std::call_once(once, [] {
    open3d::utility::Logger::GetInstance().SetPrintFunction([](const std::string& message) {
      static const std::regex colour("\x1b\\[[0-9;]*m");
      std::fprintf(stderr, "relslam: %s\n", std::regex_replace(message, colour, "").c_str());
    });
    open3d::utility::SetVerbosityLevel(open3d::utility::VerbosityLevel::Error);
  });
}

// Open3D's warnings printed while it lives (the level before restored after, also on a throw).
class Open3dWarnings {
 public:
  Open3dWarnings() { level_.Enter(); }
  ~Open3dWarnings() { level_.Exit(); }
  Open3dWarnings(const Open3dWarnings&) = delete;
  Open3dWarnings& operator=(const Open3dWarnings&) = delete;

 private:
  open3d::utility::VerbosityContextManager level_{open3d::utility::VerbosityLevel::Warning};
};

// Open3D's OpenMP loops on one thread while it lives (the caller's setting restored after).
class OneOpenMpThread {
 public:
  OneOpenMpThread() : threads_(omp_get_max_threads()) { omp_set_num_threads(1); }
  ~OneOpenMpThread() { omp_set_num_threads(threads_); }
  OneOpenMpThread(const OneOpenMpThread&) = delete;
  OneOpenMpThread& operator=(const OneOpenMpThread&) = delete;

 private:
  int threads_;
};

class RansacOpen3dExtractor final : public PlaneExtractor {
 public:
  explicit RansacOpen3dExtractor(const ExtractorSettings& settings)
      : em_(settings.em),
        options_(settings.ransac),
        threshold_(options_.distance_threshold > 0 ? options_.distance_threshold : settings.em.inlier_distance) {
    route_open3d_messages();
  }

  em::ExtractedPlanes extract(const PlanarPointFrame& frame, std::uint64_t seed) override {
    em::EmResult result = planes(frame.points, seed);
    em::set_rectangles(result.planes, frame.points, em_);
    return em::to_plane_objects(result, em_, frame.iteration);
  }

  // The planes of the points (no rectangles): SegmentPlane on the points left, pieces by DBSCAN.
  em::EmResult planes(std::span<const Eigen::Vector3d> points, std::uint64_t seed) const {
    const OneOpenMpThread one_thread;
    const std::vector<int> finite = em::finite_points(points);
    std::vector<int> left = finite;
    const double stop = std::max(static_cast<double>(em_.em2.left_min),
                                 em_.em2.left_fraction * static_cast<double>(left.size()));
    const auto min_support = static_cast<std::size_t>(em_.min_support);
    open3d::utility::random::Seed(static_cast<int>(seed % 2147483647ULL));
    em::EmResult result;
    result.ignored_points = static_cast<int>(points.size() - finite.size());
    for (int tried = 0; tried < options_.max_planes; ++tried) {
      if (static_cast<double>(left.size()) <= stop || left.size() < min_support) break;
      ++result.iterations;
      open3d::geometry::PointCloud cloud;
      cloud.points_.reserve(left.size());
      for (int i : left) cloud.points_.push_back(points[static_cast<std::size_t>(i)]);
      const auto [model, inliers] = cloud.SegmentPlane(threshold_, 3, options_.iterations);
      if (inliers.size() < min_support) break;
      add_pieces(points, left, inliers, result);
      std::vector<bool> taken(left.size(), false);
      for (std::size_t i : inliers) taken[i] = true;
      std::size_t kept = 0;
      for (std::size_t i = 0; i < left.size(); ++i)
        if (!taken[i]) left[kept++] = left[i];
      left.resize(kept);
    }
    return result;
  }

 private:
  // The inliers (indices into left) split by DBSCAN; every piece with enough points is a plane.
  void add_pieces(std::span<const Eigen::Vector3d> points, const std::vector<int>& left,
                  const std::vector<std::size_t>& inliers, em::EmResult& result) const {
    open3d::geometry::PointCloud plane;
    plane.points_.reserve(inliers.size());
    for (std::size_t i : inliers) plane.points_.push_back(points[static_cast<std::size_t>(left[i])]);
    const std::vector<int> labels =
        plane.ClusterDBSCAN(options_.cluster_eps, static_cast<std::size_t>(options_.cluster_min_points));
    std::map<int, std::vector<int>> pieces;  // ordered: deterministic
    for (std::size_t j = 0; j < labels.size(); ++j)
      if (labels[j] >= 0) pieces[labels[j]].push_back(left[inliers[j]]);
    for (auto& [label, piece] : pieces) {
      if (piece.size() < static_cast<std::size_t>(em_.min_support)) continue;
      em::EmPlane p;
      std::sort(piece.begin(), piece.end());
      p.points = std::move(piece);
      if (em::refit(p, points)) result.planes.push_back(std::move(p));
    }
  }

  em::EmOptions em_;
  RansacOptions options_;
  double threshold_;
};

}  // namespace

std::unique_ptr<PlaneExtractor> make_ransac_open3d_extractor(const ExtractorSettings& settings) {
  return std::make_unique<RansacOpen3dExtractor>(settings);
}

em::EmResult ransac_open3d_planes(std::span<const Eigen::Vector3d> points, const ExtractorSettings& settings,
                                  std::uint64_t seed) {
  return RansacOpen3dExtractor(settings).planes(points, seed);
}

em::EmResult segment_plane_planes(std::span<const Eigen::Vector3d> points, const SegmentPlaneOptions& o,
                                  std::uint64_t seed) {
  const OneOpenMpThread one_thread;
  route_open3d_messages();
  open3d::utility::random::Seed(static_cast<int>(seed % 2147483647ULL));
  em::EmResult result;
  std::vector<int> left = em::finite_points(points);
  result.ignored_points = static_cast<int>(points.size() - left.size());
  for (int tried = 0; tried < o.max_planes && left.size() >= static_cast<std::size_t>(o.min_inliers); ++tried) {
    ++result.iterations;
    open3d::geometry::PointCloud cloud;
    cloud.points_.reserve(left.size());
    for (int i : left) cloud.points_.push_back(points[static_cast<std::size_t>(i)]);
    const auto [model, inliers] = cloud.SegmentPlane(o.distance, 3, o.iterations);
    if (inliers.size() < static_cast<std::size_t>(o.min_inliers)) break;
    em::EmPlane plane;
    std::vector<bool> taken(left.size(), false);
    for (std::size_t i : inliers) taken[i] = true, plane.points.push_back(left[i]);
    std::sort(plane.points.begin(), plane.points.end());
    if (em::refit(plane, points)) result.planes.push_back(std::move(plane));
    std::size_t kept = 0;
    for (std::size_t i = 0; i < left.size(); ++i)
      if (!taken[i]) left[kept++] = left[i];
    left.resize(kept);
  }
  return result;
}

PointCloudFrame read_open3d_points(const std::filesystem::path& path) {
  route_open3d_messages();
  open3d::geometry::PointCloud cloud;
  open3d::io::ReadPointCloudOption options;
  options.print_progress = false;
  bool read = false;
  {
    const Open3dWarnings warnings;
    read = open3d::io::ReadPointCloud(path.string(), cloud, options);
  }
  if (!read) throw InputError(path.string(), 0, "", "Open3D cannot read it as a point cloud");
  PointCloudFrame frame;
  frame.source = "point file";
  frame.points.reserve(cloud.points_.size());
  for (std::size_t i = 0; i < cloud.points_.size(); ++i) {
    const Eigen::Vector3d& p = cloud.points_[i];
    if (!p.allFinite() || p.cwiseAbs().maxCoeff() > kMaxCloudCoordinate_m)
      throw InputError(path.string(), 0, "point " + std::to_string(i),
                       "not finite or beyond +-" + format_number(kMaxCloudCoordinate_m) + " m");
    frame.points.push_back(p);
  }
  return frame;
}

}  // namespace relslam::eval
