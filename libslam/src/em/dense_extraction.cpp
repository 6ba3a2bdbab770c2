#include "relslam/em/dense_extraction.hpp"

#include "relslam/em/coplanar_merging.hpp"
#include "relslam/em/em1.hpp"
#include "relslam/em/em2.hpp"
#include "relslam/em/merging.hpp"
#include "relslam/em/tight_refit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace relslam::em {
namespace {

// A plane's membership test (EmPlane::accepts) with its widened box worked out once: the
// assignment asks it for every pixel.
struct Membership {
  Eigen::Vector3d lo, hi, normal;
  double offset;
};

std::vector<Membership> memberships(const std::vector<EmPlane>& planes, const EmOptions& o) {
  std::vector<Membership> out;
  const Eigen::Vector3d margin = Eigen::Vector3d::Constant(o.bound_expansion);
  for (const EmPlane& plane : planes)
    out.push_back({plane.box.min() - margin, plane.box.max() + margin, plane.normal, plane.offset});
  return out;
}

// The nearest accepting plane (-1 for none): EmPlane::accepts, then the nearest, as
// absorb_unassigned decides.
int nearest_plane(const std::vector<Membership>& planes, const Eigen::Vector3d& p, double inlier_distance) {
  int best = -1;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < planes.size(); ++k) {
    const Membership& m = planes[k];
    if ((p.array() < m.lo.array()).any() || (p.array() > m.hi.array()).any()) continue;
    const double d = std::abs(m.normal.dot(p) + m.offset);
    if (d <= inlier_distance && d < nearest) nearest = d, best = static_cast<int>(k);
  }
  return best;
}

// Every point to the nearest plane that accepts it, every plane asked (its widened box rejects
// most points at once). Asking only the planes of the summary pixels around a pixel (four, on
// a depth image) is faster but leaves a pixel to a worse plane where its own plane owns none of
// them: on the real Kinect frame the bottom rows of the back wall, 4,700 pixels, went to a
// plane tilted 28° across the shelf below, whose summary pixels were all around them.
void assign(const DenseCloud& cloud, const std::vector<EmPlane>& planes, const EmOptions& o,
            std::vector<std::vector<int>>& members) {
  const std::vector<Membership> tests = memberships(planes, o);
  for (std::size_t i = 0; i < cloud.points.size(); ++i) {
    const Eigen::Vector3d& p = cloud.points[i];
    if (!p.allFinite()) continue;
    const int best = nearest_plane(tests, p, inlier_distance_at(o, p));
    if (best >= 0) members[static_cast<std::size_t>(best)].push_back(static_cast<int>(i));
  }
}

// A plane (nearly) through the sensor is seen edge-on: its points are no surface but a band of
// other surfaces along a line of sight, such as the pixels along the image border where a
// voxel summary keeps their rows (seen on a 640 × 480 room: a 3,840-point "wall" through the
// camera). Incidence below kMinIncidence at the plane's centroid [C]: a floor 1.8 below a lidar
// at 30 is seen at 3.4°.
constexpr double kMinIncidence = 0.0175;  // sin 1°

bool edge_on(const EmPlane& plane) {
  return std::abs(plane.offset) < kMinIncidence * plane.centroid.norm();
}

// An organised cloud's plane is a patch of its image: most of its pixels have their right and
// lower neighbours in the same plane. Pixels of several surfaces that happen to lie in one
// plane are strips, one or two pixels across: a depth image's floor row and ceiling row at one
// depth and a far wall's column at that depth lie in one plane facing the camera (seen on a
// simulated room near the camera's 8-unit limit, where the summary's rows of the floor lie 0.9
// apart and the floor's growth stops short of them: a 6-unit "wall" at 90° to the wall most of
// its pixels see). Planes whose share of such interior pixels is below kMinInterior are no
// surface [C]: a real plane's share is one less its border and missing returns (0.93 for a
// wall of 36,000 pixels at Kinect noise; the strips 0.04–0.2; a wall at the camera's depth
// limit, half its returns beyond it, 0.48, is dropped too).
constexpr double kMinInterior = 0.5;

void drop_strips(std::vector<EmPlane>& planes, const DenseCloud& cloud) {
  std::vector<int> label(cloud.points.size(), -1);
  for (std::size_t k = 0; k < planes.size(); ++k)
    for (int i : planes[k].points) label[static_cast<std::size_t>(i)] = static_cast<int>(k);
  const auto own = [&](std::size_t i, int k) { return i < label.size() && label[i] == k; };
  std::vector<EmPlane> kept;
  for (std::size_t k = 0; k < planes.size(); ++k) {
    std::size_t interior = 0;
    for (int i : planes[k].points) {
      const auto at = static_cast<std::size_t>(i);
      const bool right = (i + 1) % cloud.width != 0 && own(at + 1, static_cast<int>(k));
      interior += right && own(at + static_cast<std::size_t>(cloud.width), static_cast<int>(k));
    }
    const double share = static_cast<double>(interior) / static_cast<double>(planes[k].points.size());
    if (share >= kMinInterior) kept.push_back(std::move(planes[k]));
  }
  planes = std::move(kept);
}

// The planes `from` with the points `members` gives each (ascending), refit; those with fewer
// than min_support points, no plane or seen edge-on are dropped.
std::vector<EmPlane> with_members(const std::vector<EmPlane>& from, std::vector<std::vector<int>>& members,
                                  std::span<const Eigen::Vector3d> points, const EmOptions& o) {
  std::vector<EmPlane> planes;
  for (std::size_t k = 0; k < from.size(); ++k) {
    EmPlane plane = from[k];
    plane.points = std::move(members[k]);
    if (static_cast<int>(plane.points.size()) < o.min_support || !refit(plane, points) || edge_on(plane)) continue;
    planes.push_back(std::move(plane));
  }
  return planes;
}

// Every point asked again, now of every plane: it joins the nearest that accepts it.
void reassign(std::vector<EmPlane>& planes, const DenseCloud& cloud, const EmOptions& o) {
  std::vector<std::vector<int>> members(planes.size());
  assign(cloud, planes, o, members);
  planes = with_members(planes, members, cloud.points, o);
}

// The angle between the lowest and the highest of the plane's points as seen from the sensor
// (the origin, y up). The points of one or two scan lines of a lidar lie on cones about y
// and span at most the lines' spacing; near the sensor's height a cone is locally as flat as
// a plane and EM takes its arc for one (seen on a VLP-16 scan: seven "horizontal planes"
// between 1.2 below and 0.5 above the sensor, each one or two rings).
double elevation_span(const EmPlane& plane, std::span<const Eigen::Vector3d> points) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int i : plane.points) {
    const Eigen::Vector3d& p = points[static_cast<std::size_t>(i)];
    const double elevation = std::atan2(p.y(), std::hypot(p.x(), p.z()));
    lo = std::min(lo, elevation), hi = std::max(hi, elevation);
  }
  return hi - lo;
}

// Unorganised clouds: pieces of one surface along scan lines merged by their joint fit
// (coplanar_merging.hpp), then every point asked again, so that the points between the lines
// whose pieces EM never made planes join the merged plane.
void merge_scan_lines(std::vector<EmPlane>& planes, const DenseCloud& cloud, const EmOptions& o,
                      const DenseOptions& dense) {
  if (dense.scan_gap_per_range > 0.0 && merge_coplanar(planes, cloud.points, o, dense.scan_gap_per_range) > 0)
    reassign(planes, cloud, o);
  std::erase_if(planes, [&](const EmPlane& plane) {
    return elevation_span(plane, cloud.points) < dense.min_elevation_span_rad;
  });
}

}  // namespace

CloudSummary summarise(const DenseCloud& cloud, const DenseOptions& dense) {
  if (dense.summary_points < 3 || !(dense.voxel > 0.0))
    throw std::logic_error("summarise: summary_points must be >= 3 and voxel > 0");
  return cloud.organised() ? summarise_image(cloud.points, cloud.width, cloud.height, dense.summary_points)
                           : summarise_voxels(cloud.points, dense.summary_points, dense.voxel);
}

EmResult densify(const DenseCloud& cloud, const CloudSummary& s, const EmResult& coarse, const EmOptions& o,
                 const DenseOptions& dense) {
  std::vector<std::vector<int>> members(coarse.planes.size());
  assign(cloud, coarse.planes, o, members);

  EmResult result;
  result.iterations = coarse.iterations;
  result.ignored_points = static_cast<int>(cloud.points.size() - finite_points(cloud.points).size());
  std::vector<EmPlane> from = coarse.planes;
  for (EmPlane& plane : from)
    plane.seed_point = plane.seed_point >= 0 ? s.source[static_cast<std::size_t>(plane.seed_point)] : -1;
  result.planes = with_members(from, members, cloud.points, o);  // ascending: the passes run in index order
  // The summary's planes may hold two pieces of one surface (EM merges planes whose boxes meet;
  // at full density they do). Their pixels interleave until they are merged.
  merge_planes(result.planes, cloud.points, o);
  if (cloud.organised())
    drop_strips(result.planes, cloud);
  else
    merge_scan_lines(result.planes, cloud, o, dense);
  tight_refit(result.planes, cloud.points, o);
  set_rectangles(result.planes, cloud.points, o);
  return result;
}

DenseResult extract_dense(const DenseCloud& cloud, EmVariant variant, const EmOptions& o, const DenseOptions& dense,
                          std::uint64_t seed) {
  DenseResult out;
  out.summary = summarise(cloud, dense);
  const std::vector<Eigen::Vector3d>& points = out.summary.points;
  const EmResult coarse = variant == EmVariant::Em1 ? run_em1(points, o, seed) : run_em2(points, o, seed);
  out.result = densify(cloud, out.summary, coarse, o, dense);
  return out;
}

}  // namespace relslam::em
