#pragma once
// The one recorder of an algorithm's run, whatever the algorithm: it times each step, scores
// the estimate against the frame's truth, writes iterations.csv (the shared score columns,
// then the algorithm's own), trajectory.tum and landmarks.csv, hashes the frames it was given,
// and turns an exception, a non-finite estimate or the time budget into a recorded status
// instead of a crash (the batch goes on).

#include "relslam/core/plane_object.hpp"
#include "relslam/eval/algorithms/algorithm.hpp"
#include "relslam/eval/experiments/iteration_table.hpp"
#include "relslam/eval/io/tum_writer.hpp"
#include "relslam/eval/metrics/landmark_truth.hpp"
#include "relslam/eval/metrics/run_scorer.hpp"
#include "relslam/eval/metrics/run_summary.hpp"

#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <optional>
#include <memory>
#include <string>
#include <vector>

namespace relslam::eval {

// Past this magnitude (units) a pose or landmark coordinate has diverged: the worlds relslam
// simulates span hundreds of units and real data sets kilometres.
inline constexpr double kDivergedMagnitude = 1e9;

// A running hash of the frames an algorithm was given (iteration, point and odometry bytes, or
// plane corners and heights), so a run can show that every algorithm saw the very same stream.
class FrameDigest {
 public:
  void add(const ObservationFrame& frame);
  void add(const PlaneFrame& frame);
  std::string hex() const;

 private:
  void mix(const void* data, std::size_t bytes);
  std::uint64_t state_ = 0xcbf29ce484222325ULL;
};

// The timed part of every recorder's step: runs `step`, timing it with the wall clock. An
// exception ends the algorithm's run, not the batch: `status` becomes failed at iteration k and
// nothing is returned; otherwise status is ok and the time is returned, milliseconds.
std::optional<double> timed_step(int k, RunStatus& status, const std::function<void()>& step);

class AlgorithmRecorder {
 public:
  // Writes into dir (created).
  AlgorithmRecorder(std::unique_ptr<Algorithm> algorithm, const LandmarkTruth& truth, const std::filesystem::path& dir);

  const std::string& name() const { return algorithm_->name(); }
  void step(const ObservationFrame& observation, const TruthFrame& truth);
  // Closes the files, writes landmarks.csv; the row for summary.csv.
  SummaryRow finish();
  // The scores over the first `iterations` iterations only (after finish()), to compare with a
  // run that stopped earlier.
  SummaryRow summary_over(int iterations) const;
  // The estimated pose (world_T_robot, our axes) of every iteration processed so far.
  const std::vector<Rigid3>& trajectory() const { return scorer_.estimates(); }
  // The landmarks on its map now (world frame, our axes).
  std::vector<Eigen::Vector3d> map() const;
  const Algorithm& algorithm() const { return *algorithm_; }

 private:
  bool running() const { return status_.kind == RunStatus::Kind::NotRun || status_.kind == RunStatus::Kind::Ok; }
  void check_budget(int k, double runtime_ms);
  // A batch algorithm's work after the last frame, its revised trajectory and map rescored.
  void finish_batch();

  std::unique_ptr<Algorithm> algorithm_;
  std::filesystem::path dir_;
  std::vector<bool> truth_dynamic_;  // by true landmark id
  RunScorer scorer_;
  IterationTable iterations_;
  TumWriter trajectory_;
  FrameDigest digest_;
  RunStatus status_;  // Failed or Stopped ends the run: later frames are hashed, not processed
  std::vector<CsvField> own_fields_;
  std::deque<double> recent_;  // the last budget.iterations step times, ms
  std::vector<double> times_;  // trajectory.tum's time of each scored step
  int last_iteration_ = -1;
  std::vector<Eigen::Vector3d> last_dynamic_positions_;  // the last truth frame's
  double recent_sum_ = 0;
};

}  // namespace relslam::eval
