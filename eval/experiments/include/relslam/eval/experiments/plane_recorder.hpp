#pragma once
// The recorder of a plane algorithm's run (the counterpart of algorithm_recorder.hpp for the
// Relative Plane half): it times each step, scores the pose and the map of planes against the
// frame's truth, writes iterations.csv (the shared score
// columns, the algorithm's own, the key-point scores, then the source's own such as the
// extraction time), keypoints.csv when the algorithm
// claims key points, trajectory.tum, planes.csv and the algorithm's tables,
// hashes the frames, and turns an exception or a non-finite estimate into a recorded status.

#include "relslam/eval/algorithms/plane_algorithm.hpp"
#include "relslam/eval/experiments/algorithm_recorder.hpp"
#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/io/tum_writer.hpp"
#include "relslam/eval/metrics/plane_map_error.hpp"
#include "relslam/eval/metrics/run_summary.hpp"
#include "relslam/eval/metrics/score_column.hpp"
#include "relslam/eval/sources/plane_frame_source.hpp"

#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <vector>

namespace relslam::eval {

// What the shared columns of one plane iterations.csv row read.
struct PlaneIterationRow {
  int iteration = 0;
  PlaneMapError map_error;
  std::optional<PlanarPoseError> pose_error;  // none without a pose or a true pose
  double runtime_ms = 0;
  std::size_t planes_in_map = 0;
  std::size_t visible_planes = 0;
};

// The shared columns of iterations.csv, before the algorithm's own: iteration, map_error,
// mean_map_error, position_error, heading_error_deg, ex, ez, runtime_ms, planes_in_map,
// visible_planes.
const std::vector<ScoreColumn<PlaneIterationRow>>& plane_iteration_columns();

class PlaneRecorder {
 public:

  // walls: the true walls (by id, world frame), which must outlive the recorder; source_columns:
  // the source's own columns (PlaneFrameSource::frame_columns), whose fields come with each
  // frame. Writes into dir (created).
  PlaneRecorder(std::unique_ptr<PlaneAlgorithm> algorithm, const std::vector<PlaneObject>& walls,
                const std::vector<std::string>& source_columns, const std::filesystem::path& dir);

  const std::string& name() const { return algorithm_->name(); }
  void step(const PlaneFrame& observation, const PlaneTruthFrame& truth, const std::vector<CsvField>& measured);
  // Closes the files, writes planes.csv and the algorithm's tables; the row for summary.csv.
  SummaryRow finish();
  const PlaneAlgorithm& algorithm() const { return *algorithm_; }
  // The estimated pose of every iteration processed so far (nothing where it had none).
  const std::vector<std::optional<PlanarPose>>& trajectory() const { return estimates_; }
  const WallVotes& votes() const { return votes_; }

 private:
  bool running() const { return status_.kind == RunStatus::Kind::NotRun || status_.kind == RunStatus::Kind::Ok; }
  // finish's parts: planes.csv (each mapped plane against its true wall) with the map's counts
  // for the row; the row's trajectory scores; the scores only the plane half has.
  struct MapCounts {
    int walls_mapped = 0;  // distinct true walls a mapped plane stands for
    int duplicates = 0;    // second planes for one face of a wall
  };
  MapCounts write_planes_table();
  void score_trajectory(SummaryRow& row) const;
  PlanarScores planar_scores(int walls_mapped);
  // "" or why the estimate left the truth (relslam/eval/metrics/truth_departure.hpp).
  std::string departure() const;

  std::unique_ptr<PlaneAlgorithm> algorithm_;
  const std::vector<PlaneObject>& walls_;
  std::filesystem::path dir_;
  CsvWriter iterations_;
  std::optional<CsvWriter> keypoints_;  // when the algorithm claims key points
  TumWriter trajectory_;
  FrameDigest digest_;
  RunStatus status_;
  WallVotes votes_;
  std::set<int> walls_seen_;
  std::vector<std::optional<PlanarPose>> estimates_;
  std::vector<std::optional<PlanarPose>> truths_;  // none where the source knows no true pose
  std::vector<int> iterations_done_;  // each step's iteration, for the truth check
  std::vector<double> runtimes_ms_;
  std::vector<double> mean_map_errors_;
  PlaneMapError last_map_error_;
  std::optional<PlanarPoseError> last_pose_error_;
  double max_position_error_ = 0;
  long long key_points_checked_ = 0, key_points_wrong_ = 0;
  int wrong_key_point_iterations_ = 0;
  long long wrong_valid_ = 0;  // valid poses off the truth by more than kWrongValidBound
  std::vector<CsvField> fields_;  // reused row buffer
};

}  // namespace relslam::eval
