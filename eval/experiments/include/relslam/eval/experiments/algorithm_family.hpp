#pragma once
// An algorithm family: the frames an algorithm takes, the recorder that times and scores its run,
// the recorders of a scenario's algorithms, its summary columns and its replay, for each half of
// the workbench. The run skeleton (run_skeleton.hpp) and the replay (replay.hpp) are written once
// over them; a new half is one more family here and one more case in with_family.

#include "relslam/eval/config/scenario_half.hpp"
#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/algorithm_recorder.hpp"
#include "relslam/eval/experiments/plane_recorder.hpp"
#include "relslam/eval/experiments/plane_replay.hpp"
#include "relslam/eval/experiments/point_replay.hpp"
#include "relslam/eval/experiments/replay.hpp"
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
  static constexpr ScenarioHalf half = ScenarioHalf::Points;
  using Source = FrameSource;
  using Recorder = AlgorithmRecorder;
  using Replay = eval::Replay<PointReplay>;
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
  static const std::vector<SummaryColumn>& summary_columns() { return eval::summary_columns(half); }
};

// The plane half: plane frames, scored against the true walls (thesis Chapter 4).
struct PlaneFamily {
  static constexpr ScenarioHalf half = ScenarioHalf::Planes;
  using Source = PlaneFrameSource;
  using Recorder = PlaneRecorder;
  using Replay = eval::Replay<PlaneReplay>;
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
  static const std::vector<SummaryColumn>& summary_columns() { return eval::summary_columns(half); }
};

// visit(PointFamily{}) or visit(PlaneFamily{}) as `half` says (half_of the scenario's kind): how
// code written once over the family finds the family of a run it did not start (a replay).
template <class Visit>
decltype(auto) with_family(ScenarioHalf half, Visit&& visit) {
  if (half == ScenarioHalf::Planes) return visit(PlaneFamily{});
  return visit(PointFamily{});
}

}  // namespace relslam::eval
