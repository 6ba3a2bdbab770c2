#pragma once
// summary.csv: one row per algorithm of a run (harness).

#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/metrics/trajectory_error.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace relslam::eval {

// Median, 95th percentile and maximum of per-iteration times, milliseconds.
struct RuntimeStats {
  double median_ms = 0;
  double p95_ms = 0;
  double max_ms = 0;
  double mean_ms = 0;
};
RuntimeStats runtime_stats(std::vector<double> times_ms);

// How an algorithm's run ended: summary.csv's status column.
struct RunStatus {
  enum class Kind {
    NotRun,       // never stepped
    Ok,           // processed every frame
    Failed,       // an exception, a non-finite estimate, or the algorithm gave up
    Stopped,      // over its time budget: the rest of the stream was not processed
    Ratio,        // not a run: the row of ratios between two runs
    Interrupted,  // SIGINT or SIGTERM ended the stream early: the row covers the frames before it
    Lost,         // processed every frame, but its pose was not its own registration for most of them
  };
  Kind kind = Kind::NotRun;
  int iteration = -1;  // where it failed or stopped; -1 when no single iteration is to blame
  std::string reason;  // why, for people

  static RunStatus ok() { return {Kind::Ok, -1, ""}; }
  static RunStatus failed(int iteration, std::string reason) { return {Kind::Failed, iteration, std::move(reason)}; }
  static RunStatus stopped(int iteration, std::string reason) { return {Kind::Stopped, iteration, std::move(reason)}; }
  // `iteration` is the first frame the run did not process.
  static RunStatus interrupted(int iteration) { return {Kind::Interrupted, iteration, ""}; }
  static RunStatus lost(std::string reason) { return {Kind::Lost, -1, std::move(reason)}; }
  bool is_ok() const { return kind == Kind::Ok; }
  // "ok", "failed at iteration 30: why", "failed: why", "stopped at iteration 4: why",
  // "interrupted at iteration 2240", "lost: pose from unmapped points in 213 of 250 iterations",
  // "ratio", "not run".
  std::string text() const;
};
// The kind alone: "ok", "failed", "stopped", "interrupted", "lost", "ratio", "not run".
std::string_view to_string(RunStatus::Kind kind);

// The scores of a planar run that the point columns lack.
struct PlanarScores {
  double final_heading_error_deg = 0;  // at the last iteration with a pose
  double max_position_error = 0;       // over the iterations with a pose
  double pose_valid_fraction = 0;      // iterations with a pose / iterations processed
  int walls_mapped = 0;                // distinct true walls that a mapped plane stands for
  int walls_seen = 0;                  // distinct true walls observed
  // Key-point claims (keypoints.csv) found right, share of those checked; NaN without claims.
  double key_point_accuracy = 0;
  int wrong_key_point_iterations = 0;  // iterations with at least one wrong claim
};

struct SummaryRow {
  std::string algorithm;
  RunStatus status;
  int iterations = 0;
  double final_landmark_error = 0;       // sum over the map (thesis metric)
  double final_mean_landmark_error = 0;  // per landmark on the map
  double mean_landmark_error = 0;        // per landmark, averaged over iterations
  double final_position_error = 0;
  TrajectoryError trajectory;  // ATE (unaligned: the frames coincide; and aligned), RPE
  int landmarks_on_map = 0;
  int duplicates = 0;  // map landmarks sharing their true landmark with another
  RuntimeStats runtime;
  double peak_rss_mb = 0;    // the whole process, at the end of this algorithm's run
  std::string input_digest;  // hash of the observation frames it was given
  // Planar runs: the landmark scores above are those of the mapped planes (the summed and mean
  // key-point error e_ends, planes on the map, planes sharing the same face of a wall), and
  // these are set.
  std::optional<PlanarScores> planar;
  // The algorithm's own columns (e.g. Relative Plane's roll-back counts), after all the others;
  // a row without one of another row's columns leaves it empty.
  std::vector<std::string> own_columns;
  std::vector<CsvField> own_fields;
};

// A signal stopped the frames before `iteration`: every row still "ok" becomes "interrupted at
// iteration <iteration>", so no table counts a cut run as finished; failed and stopped rows keep
// the reason they ended for.
void mark_interrupted(std::vector<SummaryRow>& rows, int iteration);

// Element-wise a / b of the scores (landmark, position, trajectory errors and run times).
SummaryRow ratio_row(const SummaryRow& a, const SummaryRow& b);

// Peak resident memory of this process so far, megabytes.
double peak_rss_mb();

}  // namespace relslam::eval
