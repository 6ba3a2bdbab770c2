#pragma once
// E29 (thesis 3.5.4): EM1, EM2 and the Open3D baseline
// (when built) on the identical point frames of a planar point-sensor scenario, one frame at a
// time, each frame through every extractor in turn (the order rotating from frame to frame, so
// no extractor always finds the points warm in the cache). Each extractor is scored and timed
// by the run's own PointExtraction (sources/point_extraction.hpp); em_compare.csv holds one row
// per frame. The thesis: "EM2 is about twice as fast as EM1" with similar quality.

#include "relslam/eval/config/scenario_loading.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace relslam::eval {

// One extractor over the compared frames.
struct EmCompareSummary {
  std::string extractor;
  int frames = 0;
  double median_ms = 0;
  double mean_recall = 0;     // frame means
  double mean_precision = 0;
  double mean_normal_error_deg = 0;  // mean over the frames with a correct plane
};

// em_compare.csv's columns: iteration, n_points, n_true_visible, then for each extractor x in
// kPlaneExtractorKinds order that this build has: ms_x and the score columns of em_frames.csv
// but n_points and n_true_visible (n_planes_x, recall_x, ..., mean_end_err_x).
std::vector<std::string> em_compare_columns();

// Runs the comparison over the scenario's frames (planar.iterations of them; 0: the whole path)
// and writes dir/em_compare.csv. InputError at planar.sensor unless the scenario is planar with
// the point sensor.
std::vector<EmCompareSummary> run_em_compare(const LoadedScenario& loaded, const std::filesystem::path& dir);

}  // namespace relslam::eval
