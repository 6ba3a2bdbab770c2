#include "filter_run.hpp"

#include "relslam/eval/csv_writer.hpp"

#include <algorithm>
#include <chrono>

namespace relslam::eval {

std::string mrpt_message(const std::string& what) {
  const std::size_t start = what.find("Message:");
  std::string line = start == std::string::npos ? what : what.substr(start + 8);
  line = line.substr(0, line.find('\n'));
  const std::size_t first = line.find_first_not_of(' ');
  return first == std::string::npos ? "" : line.substr(first);
}

std::vector<int> unknown_association_slots(const std::map<std::size_t, std::size_t>& associations, std::size_t rows,
                                           std::size_t before) {
  std::vector<int> out(rows, -1);
  for (const auto& [row, slot] : associations)
    if (row < rows) out[row] = static_cast<int>(slot);
  std::size_t next = before;
  for (std::size_t r = 0; r < rows; ++r)
    if (out[r] < 0) out[r] = static_cast<int>(next++);
  return out;
}

FilterRun::FilterRun(std::string name, TimeBudget budget, const LandmarkTruth& truth, const std::filesystem::path& dir)
    : name_(std::move(name)),
      budget_(budget),
      dir_(dir),
      scorer_(truth),
      iterations_(dir / "iterations.csv", {}),
      trajectory_(dir / "trajectory.tum") {}

void FilterRun::step(const ObservationFrame& observation, const TruthFrame& truth) {
  digest_.add(observation);
  if (!status_.empty()) return;  // failed or stopped: the rest of the stream is not processed
  const int k = observation.iteration;
  const std::size_t before = map_size();
  const auto start = std::chrono::steady_clock::now();
  try {
    process(observation, truth);
  } catch (const std::exception& e) {
    status_ = "failed at iteration " + std::to_string(k) + ": " + mrpt_message(e.what());
    return;
  }
  const double runtime_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  // Scoring, outside the timed region.
  const Rigid3 estimate = pose();
  map_.resize(map_size());
  for (std::size_t i = 0; i < map_.size(); ++i) map_[i] = landmark(i);
  if (!estimate.translation.allFinite() || !estimate.rotation.allFinite() ||
      std::any_of(map_.begin(), map_.end(), [](const Eigen::Vector3d& p) { return !p.allFinite(); })) {
    status_ = "failed at iteration " + std::to_string(k) + ": the filter state became NaN";
    return;
  }
  scorer_.associate(assignment(observation.points.size(), before, truth.landmark_ids), truth.landmark_ids);
  all_ids_.resize(map_.size());
  for (std::size_t i = 0; i < map_.size(); ++i) all_ids_[i] = static_cast<int>(i);  // an EKF update moves every landmark
  const IterationScore s =
      scorer_.score(k, estimate, truth, all_ids_, [&](int id) { return std::optional(map_[id]); }, runtime_ms);
  iterations_.row(k, s, runtime_ms, observation.points.size());
  trajectory_.write(static_cast<double>(k), estimate);

  // The mean of the last budget_.iterations steps, so neither one slow step nor a filter
  // alternating slow and fast ones escapes the budget.
  recent_.push_back(runtime_ms);
  recent_sum_ += runtime_ms;
  if (static_cast<int>(recent_.size()) > budget_.iterations) {
    recent_sum_ -= recent_.front();
    recent_.pop_front();
  }
  if (static_cast<int>(recent_.size()) == budget_.iterations && recent_sum_ > budget_.ms * budget_.iterations)
    status_ = "stopped at iteration " + std::to_string(k) + ": over the time budget (" +
              std::to_string(static_cast<int>(budget_.ms)) + " ms) on average over " + std::to_string(budget_.iterations) +
              " iterations";
}

SummaryRow FilterRun::finish() {
  iterations_.close();
  trajectory_.close();
  CsvWriter landmarks(dir_ / "landmarks.csv", {"id", "x", "y", "z", "true_id", "error", "level"});
  std::vector<int> ids;
  for (std::size_t i = 0; i < map_.size(); ++i) {
    ids.push_back(static_cast<int>(i));
    landmarks.row(i, map_[i].x(), map_[i].y(), map_[i].z(), scorer_.majority_truth(static_cast<int>(i)),
                  scorer_.error_of(static_cast<int>(i)), "ekf");
  }
  landmarks.close();
  SummaryRow row = summary_over(static_cast<int>(scorer_.scored()));
  row.landmarks_on_map = static_cast<int>(map_.size());
  row.duplicates = scorer_.duplicates(ids);
  row.peak_rss_mb = peak_rss_mb();
  return row;
}

SummaryRow FilterRun::summary_over(int iterations) const {
  SummaryRow row;
  row.algorithm = name_;
  row.status = status_.empty() ? "ok" : status_;
  scorer_.fill(row, static_cast<std::size_t>(iterations));
  row.input_digest = digest_.hex();
  return row;
}

}  // namespace relslam::eval
