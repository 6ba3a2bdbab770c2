#include "relslam/eval/metrics/run_scorer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace relslam::eval {

void RunScorer::associate(const std::vector<int>& assignment, const std::vector<int>& true_ids) {
  for (std::size_t i = 0; i < assignment.size(); ++i) {
    if (assignment[i] < 0 || true_ids[i] < 0) continue;
    if (static_cast<std::size_t>(assignment[i]) >= votes_.size())
      votes_.resize(static_cast<std::size_t>(assignment[i]) + 1);
    ++votes_[assignment[i]][true_ids[i]];
  }
}

IterationScore RunScorer::score(const Rigid3& estimate, const TruthFrame& truth, const std::vector<int>& changed,
                                const std::function<std::optional<Eigen::Vector3d>(int)>& position_of,
                                double runtime_ms) {
  errors_.update(truth.dynamic_positions, changed, position_of);
  constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();  // written as empty fields
  IterationScore s;
  s.landmarks_on_map = errors_.count();
  s.landmark_error = truth_known_ ? errors_.sum() : kUnknown;
  s.mean_landmark_error = truth_known_ ? errors_.mean() : kUnknown;
  s.axis_error = truth.pose_known ? Eigen::Vector3d(estimate.translation - truth.world_T_robot.translation)
                                  : Eigen::Vector3d::Constant(kUnknown);
  s.position_error = s.axis_error.norm();
  poses_known_ = poses_known_ && truth.pose_known;
  runtimes_.push_back(runtime_ms);
  history_.push_back(s);
  estimates_.push_back(estimate);
  truths_.push_back(truth.world_T_robot);
  iterations_.push_back(truth.iteration);
  return s;
}

void RunScorer::revise(const std::vector<Rigid3>& poses, const std::vector<Eigen::Vector3d>& dynamic_positions,
                       const std::vector<int>& changed,
                       const std::function<std::optional<Eigen::Vector3d>(int)>& position_of) {
  if (history_.empty()) return;
  if (poses.size() == estimates_.size()) estimates_ = poses;
  errors_.update(dynamic_positions, changed, position_of);
  IterationScore& last = history_.back();
  last.landmarks_on_map = errors_.count();
  if (truth_known_) {
    last.landmark_error = errors_.sum();
    last.mean_landmark_error = errors_.mean();
  }
  if (!std::isnan(last.position_error)) {  // the last truth pose is known
    last.axis_error = estimates_.back().translation - truths_.back().translation;
    last.position_error = last.axis_error.norm();
  }
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

std::string RunScorer::departure(std::size_t iterations, std::size_t first) const {
  const std::size_t n = std::min(iterations, history_.size());
  if (!poses_known_ || n == 0) return "";
  std::vector<Eigen::Vector3d> path;
  std::vector<PositionErrorAt> errors;
  for (std::size_t k = 0; k < n; ++k) {
    path.push_back(truths_[k].translation);
    if (k >= first) errors.push_back({iterations_[k], (estimates_[k].translation - truths_[k].translation).norm()});
  }
  return truth_departure(errors, path_extent(path));
}

void RunScorer::fill(SummaryRow& row, std::size_t iterations, std::size_t first) const {
  const std::size_t n = std::min(iterations, history_.size());
  row.iterations = static_cast<int>(n);
  if (n == 0) return;
  const IterationScore& last = history_[n - 1];
  row.final_landmark_error = last.landmark_error;
  row.final_mean_landmark_error = last.mean_landmark_error;
  double mean_sum = 0;
  for (std::size_t k = 0; k < n; ++k) mean_sum += history_[k].mean_landmark_error;
  row.mean_landmark_error = mean_sum / static_cast<double>(n);
  row.final_position_error = last.position_error;
  first = std::min(first, n - 1);
  if (poses_known_) {
    const auto from = static_cast<std::ptrdiff_t>(first), to = static_cast<std::ptrdiff_t>(n);
    row.trajectory = trajectory_error({estimates_.begin() + from, estimates_.begin() + to},
                                      {truths_.begin() + from, truths_.begin() + to});
  } else {
    const double unknown = std::numeric_limits<double>::quiet_NaN();
    row.trajectory = {unknown, unknown, unknown, unknown};
  }
  row.runtime = runtime_stats({runtimes_.begin(), runtimes_.begin() + static_cast<std::ptrdiff_t>(n)});
}

}  // namespace relslam::eval
