// The baseline plane extractor (issue 14 §3): Open3D's RANSAC plane segmentation
// (PointCloud::SegmentPlane) repeated on the points left, each plane's inliers split into
// connected pieces by ClusterDBSCAN (RANSAC's plane is infinite: collinear walls and the far
// side of a gap would otherwise be one plane), each piece refit by TLS and converted by the same
// spec §4.5 code as EM's planes. Seeded per frame through utility::random::Seed, and Open3D
// runs on one OpenMP thread like EM: SegmentPlane's threads draw from the one generator in
// whatever order they run, which made two runs differ, and on a shared machine the threads
// only slowed it down. Open3D stays inside this file.
#include "extractors.hpp"

#include "relslam/em/em_plane.hpp"

#include <open3d/geometry/PointCloud.h>
#include <open3d/utility/Logging.h>
#include <open3d/utility/Random.h>

#include <omp.h>

#include <algorithm>
#include <map>

namespace relslam::eval {
namespace {

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
    open3d::utility::SetVerbosityLevel(open3d::utility::VerbosityLevel::Error);
  }

  em::ExtractedPlanes extract(const PlanarPointFrame& frame, std::uint64_t seed) override {
    const OneOpenMpThread one_thread;
    const std::vector<int> finite = em::finite_points(frame.points);
    std::vector<int> left = finite;
    const double stop = std::max(static_cast<double>(em_.em2.left_min),
                                 em_.em2.left_fraction * static_cast<double>(left.size()));
    const auto min_support = static_cast<std::size_t>(em_.min_support);
    open3d::utility::random::Seed(static_cast<int>(seed % 2147483647ULL));
    em::EmResult result;
    result.ignored_points = static_cast<int>(frame.points.size() - finite.size());
    for (int tried = 0; tried < options_.max_planes; ++tried) {
      if (static_cast<double>(left.size()) <= stop || left.size() < min_support) break;
      ++result.iterations;
      open3d::geometry::PointCloud cloud;
      cloud.points_.reserve(left.size());
      for (int i : left) cloud.points_.push_back(frame.points[static_cast<std::size_t>(i)]);
      const auto [model, inliers] = cloud.SegmentPlane(threshold_, 3, options_.iterations);
      if (inliers.size() < min_support) break;
      add_pieces(frame, left, inliers, result);
      std::vector<bool> taken(left.size(), false);
      for (std::size_t i : inliers) taken[i] = true;
      std::size_t kept = 0;
      for (std::size_t i = 0; i < left.size(); ++i)
        if (!taken[i]) left[kept++] = left[i];
      left.resize(kept);
    }
    em::set_rectangles(result.planes, frame.points, em_);
    return em::to_plane_objects(result, em_, frame.iteration);
  }

 private:
  // The inliers (indices into left) split by DBSCAN; every piece with enough points is a plane.
  void add_pieces(const PlanarPointFrame& frame, const std::vector<int>& left, const std::vector<std::size_t>& inliers,
                  em::EmResult& result) const {
    open3d::geometry::PointCloud plane;
    plane.points_.reserve(inliers.size());
    for (std::size_t i : inliers) plane.points_.push_back(frame.points[static_cast<std::size_t>(left[i])]);
    const std::vector<int> labels =
        plane.ClusterDBSCAN(options_.cluster_eps, static_cast<std::size_t>(options_.cluster_min_points));
    std::map<int, std::vector<int>> pieces;  // ordered: deterministic
    for (std::size_t j = 0; j < labels.size(); ++j)
      if (labels[j] >= 0) pieces[labels[j]].push_back(left[inliers[j]]);
    for (auto& [label, points] : pieces) {
      if (points.size() < static_cast<std::size_t>(em_.min_support)) continue;
      em::EmPlane p;
      std::sort(points.begin(), points.end());
      p.points = std::move(points);
      if (em::refit(p, frame.points)) result.planes.push_back(std::move(p));
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

}  // namespace relslam::eval
