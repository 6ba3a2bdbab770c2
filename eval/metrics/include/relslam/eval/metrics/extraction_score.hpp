#pragma once
// How well one frame's plane extraction did:
// the visible wall pieces as ground truth, SegComp's five counts (segcomp.hpp) between them and
// the extracted planes' points, and the errors of the correct detections against their walls.

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"
#include "relslam/em/options.hpp"
#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/metrics/segcomp.hpp"

#include <Eigen/Core>

#include <span>
#include <string>
#include <vector>

namespace relslam::eval {

// Tags: [T] Hoover et al. 1996, [C] chosen here.
struct ExtractionScoreOptions {
  double overlap = 0.8;  // SegComp's tolerance T [T: the paper's reported setting]
  // A wall's visible points split into pieces where consecutive points along the wall are
  // further apart than this, units: EM's merge joins planes whose boxes widened by e_exp = 0.3
  // touch, so a gap under 2 e_exp is one piece to it [C].
  double piece_gap = 0.6;
  // A piece counts as ground truth with at least this many points spread over at least this
  // length: EM's N_min, and the conversion's L_min (0.3) plus two field spacings, so a sliver
  // at the frustum's edge that the conversion rightly drops is not required [C]. A plane whose
  // points are mostly on an uncounted piece is neither scored nor noise.
  int min_points = 20;
  double min_extent = 0.7;

  // The defaults with the piece gap and the minimum points of these EM constants: 2·e_exp, N_min.
  static ExtractionScoreOptions for_em(const em::EmOptions& em) {
    ExtractionScoreOptions o;
    o.piece_gap = 2.0 * em.bound_expansion;
    o.min_points = em.min_support;
    return o;
  }
};

struct ExtractionFrameScore {
  int points = 0;
  int planes = 0;          // extracted planes (after the conversion)
  int ignored_planes = 0;  // planes mostly on uncounted pieces
  int true_visible = 0;    // counted pieces
  SegCompCounts counts;
  double recall = 0;     // correct / true_visible (1 with nothing to find)
  double precision = 0;  // correct / (planes - ignored_planes) (1 with no scored plane)
  // Means over the correct detections (NaN without one): the angle between the plane's and the
  // wall's normals, |offset difference| of their lines, and the larger distance of the
  // plane's ends from the piece's outermost points (robot frame, x-z).
  double mean_normal_error_deg = 0;
  double mean_offset_error = 0;
  double mean_end_error = 0;
};

// points: the frame's points (robot frame, (x, y, z)); wall_ids[i] the true wall of points[i]
// (-1: none); walls: the true walls by id, world frame; planes[m] (robot frame) was extracted
// from the points support[m].
ExtractionFrameScore score_extraction(std::span<const Eigen::Vector3d> points, std::span<const int> wall_ids,
                                      const std::vector<PlaneObject>& walls, const PlanarPose& world_T_robot,
                                      const std::vector<PlaneObject>& planes,
                                      const std::vector<std::vector<int>>& support,
                                      const ExtractionScoreOptions& options);

// The score's columns of em_frames.csv and bench.csv (n_points ... mean_end_err, in the
// order of the extraction scores) and a score's fields for them (NaN means empty).
const std::vector<std::string>& extraction_score_columns();
void append_score_fields(const ExtractionFrameScore& score, std::vector<CsvField>& out);

}  // namespace relslam::eval
