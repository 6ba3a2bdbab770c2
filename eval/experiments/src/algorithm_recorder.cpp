#include "relslam/eval/experiments/algorithm_recorder.hpp"

#include "relslam/eval/io/csv_writer.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace relslam::eval {
namespace {

const std::filesystem::path& created(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace

// FNV-1a over raw bytes.
void FrameDigest::mix(const void* data, std::size_t n) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < n; ++i) state_ = (state_ ^ bytes[i]) * 0x100000001b3ULL;
}

void FrameDigest::add(const PlaneFrame& frame) {
  mix(&frame.iteration, sizeof frame.iteration);
  for (const PlaneObject& p : frame.planes) {
    mix(p.a.data(), 2 * sizeof(double));
    mix(p.b.data(), 2 * sizeof(double));
    mix(&p.y_lo, sizeof p.y_lo);
    mix(&p.y_hi, sizeof p.y_hi);
  }
}

void FrameDigest::add(const ObservationFrame& frame) {
  mix(&frame.iteration, sizeof frame.iteration);
  for (const Eigen::Vector3d& p : frame.points) mix(p.data(), 3 * sizeof(double));
  if (frame.odometry) {
    mix(frame.odometry->rotation.data(), 9 * sizeof(double));
    mix(frame.odometry->translation.data(), 3 * sizeof(double));
  }
}

std::string FrameDigest::hex() const {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(state_));
  return text;
}

std::optional<double> timed_step(int k, RunStatus& status, const std::function<void()>& step) {
  const auto start = std::chrono::steady_clock::now();
  try {
    step();
  } catch (const std::exception& e) {  // a bad frame ends this algorithm's run, not the batch
    status = RunStatus::failed(k, e.what());
    return std::nullopt;
  }
  status = RunStatus::ok();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

AlgorithmRecorder::AlgorithmRecorder(std::unique_ptr<Algorithm> algorithm, const LandmarkTruth& truth,
                                     const std::filesystem::path& dir)
    : algorithm_(std::move(algorithm)),
      dir_(created(dir)),
      truth_dynamic_(truth.positions.size(), false),
      scorer_(truth),
      iterations_(dir_ / "iterations.csv", algorithm_->iteration_columns()),
      trajectory_(dir_ / "trajectory.tum") {
  for (int id : truth.dynamic_ids) truth_dynamic_[id] = true;
}

void AlgorithmRecorder::step(const ObservationFrame& observation, const TruthFrame& truth) {
  digest_.add(observation);
  if (!running()) return;  // failed or stopped: the rest of the stream is not processed
  const int k = observation.iteration;
  const std::optional<double> timed = timed_step(k, status_, [&] { algorithm_->step(observation, truth); });
  if (!timed) return;
  const double runtime_ms = *timed;

  // Scoring, outside the timed region.
  algorithm_->read_out();
  const Rigid3 estimate = algorithm_->pose();
  const std::vector<int>& changed = algorithm_->changed();
  const bool finite = estimate.translation.allFinite() && estimate.rotation.allFinite() &&
                      std::all_of(changed.begin(), changed.end(), [&](int id) {
                        const auto p = algorithm_->position(id);
                        return !p || p->allFinite();
                      });
  if (!finite) {
    status_ = RunStatus::failed(k, "the estimate became NaN");
    return;
  }
  // A filter can diverge to finite numbers no world has (an EKF at 8e23 units): a failure too,
  // never an `ok` row whose errors dwarf every other run's.
  const auto diverged = [](const Eigen::Vector3d& p) { return p.lpNorm<Eigen::Infinity>() > kDivergedMagnitude; };
  if (diverged(estimate.translation) || std::any_of(changed.begin(), changed.end(), [&](int id) {
        const auto p = algorithm_->position(id);
        return p && diverged(*p);
      })) {
    status_ = RunStatus::failed(k, "the estimate diverged (a coordinate beyond 1e9 units)");
    return;
  }
  scorer_.associate(algorithm_->assignment(), truth.landmark_ids);
  const IterationScore s = scorer_.score(
      estimate, truth, changed, [&](int id) { return algorithm_->position(id); }, runtime_ms);
  own_fields_.clear();
  algorithm_->iteration_fields(own_fields_);
  iterations_.row({k, s, runtime_ms, observation.points.size()}, own_fields_);
  times_.push_back(observation.time_s.value_or(static_cast<double>(k)));
  trajectory_.write(times_.back(), estimate);
  last_iteration_ = k;
  last_dynamic_positions_ = truth.dynamic_positions;
  check_budget(k, runtime_ms);
}

void AlgorithmRecorder::check_budget(int k, double runtime_ms) {
  const std::optional<TimeBudget> budget = algorithm_->time_budget();
  if (!budget) return;
  // The mean of the last budget->iterations steps, so neither one slow step nor a filter
  // alternating slow and fast ones escapes the budget.
  recent_.push_back(runtime_ms);
  recent_sum_ += runtime_ms;
  if (static_cast<int>(recent_.size()) > budget->iterations) {
    recent_sum_ -= recent_.front();
    recent_.pop_front();
  }
  if (static_cast<int>(recent_.size()) == budget->iterations && recent_sum_ > budget->ms * budget->iterations)
    status_ = RunStatus::stopped(k, "over the time budget (" + std::to_string(static_cast<int>(budget->ms)) +
                                        " ms) on average over " + std::to_string(budget->iterations) + " iterations");
}

void AlgorithmRecorder::finish_batch() {
  if (!running() || last_iteration_ < 0) return;
  if (!timed_step(last_iteration_, status_, [&] { algorithm_->finish(); })) return;
  const std::vector<Rigid3> revised = algorithm_->revised_trajectory();
  scorer_.revise(revised, last_dynamic_positions_, algorithm_->changed(),
                 [&](int id) { return algorithm_->position(id); });
  if (revised.size() != times_.size()) return;
  TumWriter trajectory(dir_ / "trajectory.tum");  // the revised poses replace the steps'
  for (std::size_t i = 0; i < revised.size(); ++i) trajectory.write(times_[i], revised[i]);
  trajectory.close();
}

SummaryRow AlgorithmRecorder::finish() {
  iterations_.close();
  trajectory_.close();
  finish_batch();
  CsvWriter landmarks(dir_ / "landmarks.csv", algorithm_->landmark_columns());
  algorithm_->landmark_rows(
      [&](int id) {
        LandmarkScore s;
        s.true_id = scorer_.majority_truth(id);
        s.error = scorer_.error_of(id);
        // Without truth landmarks (a rawlog run) the ids are the log's own, and nothing is known to move.
        s.true_dynamic =
            s.true_id >= 0 && static_cast<std::size_t>(s.true_id) < truth_dynamic_.size() && truth_dynamic_[s.true_id];
        return s;
      },
      [&](const std::vector<CsvField>& fields) { landmarks.row_fields(fields); });
  landmarks.close();
  const std::vector<int> on_map = algorithm_->map_ids();
  SummaryRow row = summary_over(static_cast<int>(scorer_.scored()));
  row.landmarks_on_map = static_cast<int>(on_map.size());
  row.duplicates = scorer_.duplicates(on_map);
  row.peak_rss_mb = peak_rss_mb();
  row.own_columns = algorithm_->summary_columns();
  algorithm_->summary_fields(row.own_fields);
  return row;
}

SummaryRow AlgorithmRecorder::summary_over(int iterations) const {
  SummaryRow row;
  row.algorithm = name();
  row.status = status_;
  // An algorithm that gave up without throwing goes on stepping; its run is still a failure.
  if (running() && !algorithm_->failure().empty()) row.status = RunStatus::failed(-1, algorithm_->failure());
  // One whose pose was not its own for most of the run has not mapped it (lost_pose.hpp).
  else if (running() && !algorithm_->lost().empty())
    row.status = RunStatus::lost(algorithm_->lost());
  // One whose estimate stayed far from the truth has not mapped it either (truth_departure.hpp).
  else if (const std::string left = running() ? scorer_.departure(static_cast<std::size_t>(iterations),
                                                                  algorithm_->steps_before_map_frame())
                                              : "";
           !left.empty())
    row.status = RunStatus::lost(left);
  scorer_.fill(row, static_cast<std::size_t>(iterations), algorithm_->steps_before_map_frame());
  row.input_digest = digest_.hex();
  return row;
}

std::vector<Eigen::Vector3d> AlgorithmRecorder::map() const {
  std::vector<Eigen::Vector3d> out;
  for (int id : algorithm_->map_ids()) out.push_back(*algorithm_->position(id));
  return out;
}

}  // namespace relslam::eval
