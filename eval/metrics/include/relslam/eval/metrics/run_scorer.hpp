#pragma once
// Scores one algorithm's run against the truth, iteration by iteration (thesis 6.6.1): landmark
// error, position error per axis, run time, and which true landmark each estimate stands for.

#include "relslam/core/rigid.hpp"
#include "relslam/core/truth.hpp"
#include "relslam/eval/metrics/landmark_error.hpp"
#include "relslam/eval/metrics/run_summary.hpp"
#include "relslam/eval/metrics/truth_departure.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace relslam::eval {

struct IterationScore {
  double landmark_error = 0;       // sum over the map
  double mean_landmark_error = 0;  // per map landmark
  int landmarks_on_map = 0;
  double position_error = 0;
  Eigen::Vector3d axis_error = Eigen::Vector3d::Zero();  // estimate - truth, world axes
};

class RunScorer {
 public:
  explicit RunScorer(const LandmarkTruth& truth) : errors_(truth), truth_known_(truth.known) {}

  // Which true landmark each observation was (assignment[i] is the estimate it went to).
  void associate(const std::vector<int>& assignment, const std::vector<int>& true_ids);
  // After the algorithm's step: scores the pose and the changed map landmarks, records the time.
  IterationScore score(const Rigid3& estimate, const TruthFrame& truth, const std::vector<int>& changed,
                       const std::function<std::optional<Eigen::Vector3d>(int)>& position_of, double runtime_ms);

  // A batch algorithm's finished estimate, after the last score(): `poses` (one per scored
  // iteration; none leaves them) replace the scored poses, the landmarks `changed` are scored
  // again against the last truth, and the last iteration's scores become the finished ones.
  void revise(const std::vector<Rigid3>& poses, const std::vector<Eigen::Vector3d>& dynamic_positions,
              const std::vector<int>& changed, const std::function<std::optional<Eigen::Vector3d>(int)>& position_of);

  // The true landmark behind most of an estimate's observations (-1 if none).
  int majority_truth(int id) const;
  double error_of(int id) const { return errors_.error_of(id); }
  // Map landmarks beyond one per true landmark, among `ids` (the estimates on the map).
  int duplicates(const std::vector<int>& ids) const;
  // Fills the row's scores (everything but algorithm, status and landmarks_on_map) over the
  // first `iterations` scored iterations (all of them by default): a run can then be compared
  // with one that stopped earlier, at the same point.
  // Trajectory errors over the scored iterations from `first` on (the ones before had no pose).
  void fill(SummaryRow& row, std::size_t iterations = SIZE_MAX, std::size_t first = 0) const;
  // "" while the estimate kept to the truth, else why it left it (truth_departure.hpp), over
  // the same iterations as fill(); "" without a true path. Batch algorithms' revised poses count.
  std::string departure(std::size_t iterations = SIZE_MAX, std::size_t first = 0) const;
  std::size_t scored() const { return history_.size(); }
  const std::vector<Rigid3>& estimates() const { return estimates_; }

 private:
  LandmarkErrorTracker errors_;
  std::vector<std::map<int, int>> votes_;  // per estimate: true id -> observations
  std::vector<double> runtimes_;
  std::vector<IterationScore> history_;
  std::vector<Rigid3> estimates_, truths_;
  std::vector<int> iterations_;  // each scored iteration's number
  bool truth_known_;
  bool poses_known_ = true;
};

}  // namespace relslam::eval
