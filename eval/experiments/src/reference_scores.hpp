#pragma once
// Internal to the experiments layer: the summary.csv columns that score a planar run's paths
// without ground truth, against the reference algorithm's path and at a revisited place
// (metrics/reference_path.hpp).

#include "relslam/eval/config/scenario.hpp"
#include "relslam/eval/experiments/plane_recorder.hpp"
#include "relslam/eval/metrics/run_summary.hpp"

#include <memory>
#include <vector>

namespace relslam::eval {

// rows[i] belongs to recorders[i]. With output.reference_algorithm among them: every row gets
// ate_vs_reference (its own row 0); with output.revisit_frames: loop_gap_m and loop_gap_deg
// (as the path says) and, with the reference, loop_gap_vs_reference_m and _deg.
void add_reference_scores(std::vector<SummaryRow>& rows, const std::vector<std::unique_ptr<PlaneRecorder>>& recorders,
                          const OutputOptions& output);

}  // namespace relslam::eval
