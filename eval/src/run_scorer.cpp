#include "relslam/eval/run_scorer.hpp"

#include <cmath>

namespace relslam::eval {

void RunScorer::associate(const std::vector<int>& assignment, const std::vector<int>& true_ids) {
  for (std::size_t i = 0; i < assignment.size(); ++i) {
    if (assignment[i] < 0) continue;
    if (static_cast<std::size_t>(assignment[i]) >= votes_.size()) votes_.resize(static_cast<std::size_t>(assignment[i]) + 1);
    ++votes_[assignment[i]][true_ids[i]];
  }
}

IterationScore RunScorer::score(int k, const Rigid3& estimate, const TruthFrame& truth, const std::vector<int>& changed,
                                const std::function<std::optional<Eigen::Vector3d>(int)>& position_of, double runtime_ms) {
  errors_.update(k, changed, position_of);
  IterationScore s;
  s.landmark_error = errors_.sum();
  s.landmarks_on_map = errors_.count();
  s.mean_landmark_error = errors_.mean();
  s.axis_error = estimate.translation - truth.world_T_robot.translation;
  s.position_error = s.axis_error.norm();
  runtimes_.push_back(runtime_ms);
  squared_position_errors_ += s.position_error * s.position_error;
  mean_error_sum_ += s.mean_landmark_error;
  last_ = s;
  return s;
}

int RunScorer::majority_truth(int id) const {
  if (id < 0 || static_cast<std::size_t>(id) >= votes_.size()) return -1;
  int best = -1, count = 0;
  for (const auto& [truth, n] : votes_[id])
    if (n > count) best = truth, count = n;
  return best;
}

int RunScorer::duplicates(const std::vector<int>& ids) const {
  std::map<int, int> per_truth;
  for (int id : ids) ++per_truth[majority_truth(id)];
  int extra = 0;
  for (const auto& [truth, n] : per_truth) extra += truth >= 0 ? n - 1 : 0;
  return extra;
}

void RunScorer::fill(SummaryRow& row) const {
  const auto n = static_cast<double>(runtimes_.size());
  row.iterations = static_cast<int>(runtimes_.size());
  row.final_landmark_error = last_.landmark_error;
  row.final_mean_landmark_error = last_.mean_landmark_error;
  row.mean_landmark_error = n > 0 ? mean_error_sum_ / n : 0.0;
  row.final_position_error = last_.position_error;
  row.ate_rmse = n > 0 ? std::sqrt(squared_position_errors_ / n) : 0.0;
  row.runtime = runtime_stats(runtimes_);
}

}  // namespace relslam::eval
