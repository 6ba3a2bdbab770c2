#pragma once
// An algorithm family: the frames an algorithm takes, the recorder that times and scores its run,
// and the recorders of a scenario's algorithms, for each half of the workbench. The run skeleton
// (run_skeleton.hpp) is written once over them; a new half is one more family here.

#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/algorithm_recorder.hpp"
#include "relslam/eval/experiments/plane_recorder.hpp"
#include "relslam/eval/metrics/summary_columns.hpp"
#include "relslam/eval/sources/frame_source.hpp"
#include "relslam/eval/sources/plane_frame_source.hpp"

#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

namespace relslam::eval {

// The point half: range-bearing frames, scored against true landmarks (thesis Chapters 3, 6).
struct PointFamily {
  using Source = FrameSource;
  using Recorder = AlgorithmRecorder;
  // One recorder per algorithm of the scenario, writing into out/<name>/.
  static std::vector<std::unique_ptr<Recorder>> recorders(const LoadedScenario& loaded, Source& source,
                                                          const std::filesystem::path& out);
  // The Relative Point / EKF ratio row, over the iterations both processed, when both ran.
  static std::optional<SummaryRow> ratio(const std::vector<std::unique_ptr<Recorder>>& recorders,
                                         const std::vector<SummaryRow>& rows);
  // Every other algorithm over the batch optimum, the accuracy floor over all the frames (an EKF
  // stopped early is compared as it stopped), when batch_optimum ran.
  static std::vector<SummaryRow> floor_ratios(const std::vector<std::unique_ptr<Recorder>>& recorders,
                                              const std::vector<SummaryRow>& rows);
  // Scores of a row that need the other rows: none in this half.
  static void add_cross_scores(std::vector<SummaryRow>&, const std::vector<std::unique_ptr<Recorder>>&,
                               const OutputOptions&) {}
  // summary.csv's columns before the algorithms' own.
  static const std::vector<SummaryColumn>& summary_columns() { return point_summary_columns(); }
};

// The plane half: plane frames, scored against the true walls (thesis Chapter 4).
struct PlaneFamily {
  using Source = PlaneFrameSource;
  using Recorder = PlaneRecorder;
  static std::vector<std::unique_ptr<Recorder>> recorders(const LoadedScenario& loaded, Source& source,
                                                          const std::filesystem::path& out);
  // No ratio row.
  static std::optional<SummaryRow> ratio(const std::vector<std::unique_ptr<Recorder>>&,
                                         const std::vector<SummaryRow>&) {
    return std::nullopt;
  }
  static std::vector<SummaryRow> floor_ratios(const std::vector<std::unique_ptr<Recorder>>&,
                                              const std::vector<SummaryRow>&) {
    return {};
  }
  // Scores against another algorithm's path, for runs without a true one: ate_vs_reference
  // against output.reference_algorithm and the loop gap at output.revisit_frames.
  static void add_cross_scores(std::vector<SummaryRow>& rows, const std::vector<std::unique_ptr<Recorder>>& recorders,
                               const OutputOptions& output);
  static const std::vector<SummaryColumn>& summary_columns() { return plane_summary_columns(); }
};

}  // namespace relslam::eval
