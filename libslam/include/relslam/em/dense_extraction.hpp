#pragma once
// EM1 and EM2 at sensor density: a depth frame of 640 × 480 points or a lidar scan (thesis 3.5;
// the density check of 3.5.3 suggests the summary). Eigen only.
//
// EM runs on a summary of the cloud (cloud_summary.hpp), a few thousand points as dense as its
// seeding, growth and density check need; every point of the full cloud then joins the plane
// that accepts it and lies nearest (every plane is asked: a few per frame, each rejecting most
// points by its box), and each plane is fit again on all its points with the tight gate of
// tight_refit.hpp. Planes seen edge-on (through the sensor, the origin) are dropped, and pieces
// of one surface that meet at full density merged; on a lidar's scan, pieces along its scan
// lines that one plane holds merge (coplanar_merging.hpp). The planes are as exact as the full
// cloud allows while EM's cost is that of the summary.

#include "relslam/em/cloud_summary.hpp"
#include "relslam/em/em_plane.hpp"
#include "relslam/em/options.hpp"

#include <cstdint>
#include <numbers>
#include <span>

namespace relslam::em {

struct DenseOptions {
  // Points EM runs on at most [C]: 4800 is a 640 × 480 image at stride 8 (80 × 60), about one
  // point per 4 cm at 2.5 m, well inside EM's seed radius and density step; EM2 on it stays
  // within a few milliseconds.
  int summary_points = 4800;
  // Unorganised clouds: the voxel edge tried first (doubled until the summary fits), units [C].
  double voxel = 0.02;
  // Unorganised clouds: pieces of planes whose joint fit holds them both merge when their
  // boxes lie at most e_exp + scan_gap_per_range · range apart, r the smaller mean range of
  // their points (coplanar_merging.hpp) [C]. A lidar's scan lines lie 2° apart on a VLP-16: 1.1 on
  // the ground at 8 from a sensor 2.2 above it, 6 at 20; and the ground on either side of the
  // sensor's blind circle (8.2 across at 15° below) lies up to about its range apart. 0: off.
  double scan_gap_per_range = 1.2;
  // Unorganised clouds: planes whose points span a smaller elevation angle from the sensor are
  // one or two scan lines, no surface (a VLP-16's lines lie 2° apart) [C]. 0: off.
  double min_elevation_span_rad = 3.0 * std::numbers::pi / 180.0;
};

void describe(OptionsOf<DenseOptions> auto& o, auto& f) {
  f.field("summary_points", o.summary_points, "EM runs on at most this many points of the cloud", at_least(3));
  f.field("voxel", o.voxel, "unorganised clouds: first voxel edge tried for the summary, units", above(0.0));
  f.field("scan_gap_per_range", o.scan_gap_per_range,
          "unorganised clouds: coplanar pieces this far apart per unit of range merge (0: off)", at_least(0.0));
  f.degrees("min_elevation_span_deg", o.min_elevation_span_rad,
            "unorganised clouds: planes spanning a smaller elevation angle are scan lines, degrees", at_least(0.0),
            at_most(90.0));
}

enum class EmVariant : unsigned char { Em1, Em2 };

// A sensor's cloud: organised (a depth image, row-major, non-finite where no return) when
// width · height equals the points, unorganised otherwise (width = height = 0).
struct DenseCloud {
  std::span<const Eigen::Vector3d> points;
  int width = 0, height = 0;
  bool organised() const {
    return width > 0 && height > 0 && static_cast<std::size_t>(width) * static_cast<std::size_t>(height) == points.size();
  }
};

struct DenseResult {
  EmResult result;  // planes over the full cloud's indices, each with its rectangle
  CloudSummary summary;
};

// The summary EM runs on: the image grid for an organised cloud, voxels otherwise.
CloudSummary summarise(const DenseCloud& cloud, const DenseOptions& dense);

// Planes found on the summary (`coarse`, indices into summary.points; any extractor's) over the
// full cloud: every point joins the nearest plane that accepts it (options' d_in and e_exp),
// planes with fewer than min_support points or seen edge-on are dropped, pieces that now meet
// merge, an organised cloud's planes whose pixels form strips rather than a patch of the image
// are dropped, an unorganised cloud's coplanar pieces along scan lines merge
// (dense.scan_gap_per_range), then the tight refit and the rectangles. Points × planes.
EmResult densify(const DenseCloud& cloud, const CloudSummary& summary, const EmResult& coarse,
                 const EmOptions& options, const DenseOptions& dense);

// The planes of the cloud by EM1 or EM2 (run_em1 / run_em2 on the summary, seeded by `seed`).
// Requires check(options) to be empty and dense options within their describe() bounds.
DenseResult extract_dense(const DenseCloud& cloud, EmVariant variant, const EmOptions& options,
                          const DenseOptions& dense, std::uint64_t seed);

}  // namespace relslam::em
