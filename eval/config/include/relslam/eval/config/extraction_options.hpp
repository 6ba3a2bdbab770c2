#pragma once
// Which plane extractor turns the point sensor's frames into the Relative Plane algorithm's
// plane frames (planar.sensor "points"; thesis Chapter 5, 3.5), and
// the settings of the Open3D RANSAC baseline. The EM constants are libslam's
// (em/options.hpp), taken at EmOptions::for_point_sigma(planar.noise.point_sigma). Keys under
// relative_plane.* (extractor, ransac.*). Tags: [T] thesis, [R] recommended in the design, [C] chosen here.

#include "relslam/core/option_fields.hpp"
#include "relslam/em/options.hpp"

#include <string_view>

namespace relslam::eval {

enum class PlaneExtractorKind {
  Em2,           // EM algorithm 2, incremental (thesis 3.5.3) [T: the faster one]
  Em1,           // EM algorithm 1, batch (thesis 3.5.2) [T]
  RansacOpen3d,  // the baseline: Open3D's sequential RANSAC plus DBSCAN pieces [C]
};
inline constexpr PlaneExtractorKind kPlaneExtractorKinds[] = {PlaneExtractorKind::Em2, PlaneExtractorKind::Em1,
                                                              PlaneExtractorKind::RansacOpen3d};
inline std::string_view to_string(PlaneExtractorKind kind) {
  switch (kind) {
    case PlaneExtractorKind::Em1: return "em1";
    case PlaneExtractorKind::RansacOpen3d: return "ransac_open3d";
    case PlaneExtractorKind::Em2: break;
  }
  return "em2";
}

// The baseline: PointCloud::SegmentPlane on the points left, repeated; each plane's inliers
// split into connected pieces by ClusterDBSCAN; each piece refit and converted like an EM
// plane. Like EM it drops planes and pieces under em.min_support points, and it stops by EM2's
// rule: at most max(em.em2.left_min, em.em2.left_fraction · points) points left [C].
struct RansacOptions {
  // Inlier distance of SegmentPlane, units; 0: EM's d_in (relative_plane.em.inlier_distance),
  // so both extractors accept the same band [C].
  double distance_threshold = 0.0;
  int iterations = 1000;  // RANSAC iterations per plane [C: Open3D's example value]
  int max_planes = 30;    // planes looked for per frame at most [C]
  // DBSCAN: neighbours within eps (units) join a piece; eps below EM's merge reach (2 e_exp =
  // 0.6) and above the field's spacing (0.2) plus noise [C].
  double cluster_eps = 0.5;
  int cluster_min_points = 4;  // DBSCAN's core-point neighbours [C]
};

void describe(OptionsOf<RansacOptions> auto& o, auto& f) {
  f.field("distance_threshold", o.distance_threshold, "RANSAC inlier distance, units; 0: em.inlier_distance",
          at_least(0.0));
  f.field("iterations", o.iterations, "RANSAC iterations per plane", at_least(1));
  f.field("max_planes", o.max_planes, "planes looked for per frame at most", at_least(1));
  f.field("cluster_eps", o.cluster_eps, "DBSCAN neighbourhood radius splitting a plane into pieces, units",
          above(0.0));
  f.field("cluster_min_points", o.cluster_min_points, "DBSCAN core-point neighbours", at_least(1));
}

struct ExtractionOptions {
  PlaneExtractorKind extractor = PlaneExtractorKind::Em2;  // [T: EM2, "about twice as fast"]
  em::EmOptions em;
  RansacOptions ransac;
};

void describe(OptionsOf<ExtractionOptions> auto& o, auto& f) {
  f.choice("extractor", o.extractor, "planes from the point sensor's points: em2, em1 or ransac_open3d (baseline)",
           kPlaneExtractorKinds);
  f.nested("em", o.em);
  f.nested("ransac", o.ransac);
}

}  // namespace relslam::eval
