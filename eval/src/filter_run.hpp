#pragma once
// Internal to relslam_eval: what the MRPT EKF baselines (6D, 2D) share as algorithms of a run —
// the files, the scoring, and turning an exception, a NaN state or the time budget into a
// recorded status instead of a crash (spec mrpt §1.8).

#include "relslam/eval/algorithm_run.hpp"
#include "relslam/eval/iteration_table.hpp"
#include "relslam/eval/landmark_truth.hpp"
#include "relslam/eval/run_scorer.hpp"
#include "relslam/eval/tum_writer.hpp"

#include <deque>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace relslam::eval {

struct TimeBudget {
  double ms = 1000.0;   // per iteration
  int iterations = 20;  // a mean over this many consecutive iterations above it stops the filter
};

class FilterRun : public AlgorithmRun {
 public:
  const std::string& name() const override { return name_; }
  void step(const ObservationFrame& observation, const TruthFrame& truth) final;
  SummaryRow finish() final;
  SummaryRow summary_over(int iterations) const final;
  const std::vector<Rigid3>& trajectory() const final { return scorer_.estimates(); }
  std::vector<Eigen::Vector3d> map() const final { return map_; }

 protected:
  FilterRun(std::string name, TimeBudget budget, const LandmarkTruth& truth, const std::filesystem::path& dir);

  // One filter step on this frame; the only timed work. Throws when the filter fails.
  virtual void process(const ObservationFrame& observation, const TruthFrame& truth) = 0;
  virtual std::size_t map_size() const = 0;
  // After process(): the filter's pose (world_T_robot) and landmarks, in our axes.
  virtual Rigid3 pose() const = 0;
  virtual Eigen::Vector3d landmark(std::size_t index) const = 0;
  // The map slot each observation row went to (-1 unknown); `before` = landmarks before the step.
  virtual std::vector<int> assignment(std::size_t rows, std::size_t before, const std::vector<int>& true_ids) const = 0;

 private:
  std::string name_;
  TimeBudget budget_;
  std::filesystem::path dir_;
  RunScorer scorer_;
  IterationTable iterations_;
  TumWriter trajectory_;
  std::vector<Eigen::Vector3d> map_;
  std::vector<int> all_ids_;
  std::deque<double> recent_;  // the last budget_.iterations step times, ms
  double recent_sum_ = 0;
  std::string status_;  // empty while running
  FrameDigest digest_;
};

// MRPT's exception text, its first line of message.
std::string mrpt_message(const std::string& what);

// Map slot of each observation row after a step with data association (no ids): the filter's
// associations (row -> slot); rows it left unassociated became new landmarks, appended in row
// order from `before` (CKalmanFilterCapable's "add new landmarks" step).
std::vector<int> unknown_association_slots(const std::map<std::size_t, std::size_t>& associations, std::size_t rows,
                                           std::size_t before);

}  // namespace relslam::eval
