// MRPT's 6D range-bearing EKF-SLAM (CRangeBearingKFSLAM) as one algorithm of a run: the
// thesis's baseline (6.7), driven as spec mrpt §1.8 and §6 say to avoid MRPT 2.5.8's traps.
#include "ekf6d_run.hpp"

#include "mrpt_observation.hpp"
#include "relslam/eval/csv_writer.hpp"
#include "relslam/eval/iteration_table.hpp"
#include "relslam/eval/range_bearing.hpp"
#include "relslam/eval/run_scorer.hpp"
#include "relslam/eval/tum_writer.hpp"

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/slam/CRangeBearingKFSLAM.h>

#include <chrono>
#include <cmath>
#include <map>

namespace relslam::eval {
namespace {

using mrpt::slam::CRangeBearingKFSLAM;

// The filter with its landmark-id table readable: with known association that table is the
// authority on which state slot holds which landmark (MRPT keeps it protected).
class Filter final : public CRangeBearingKFSLAM {
 public:
  // State slot of landmark `id`, -1 when the filter has not added it.
  int slot_of(int id) const {
    unsigned int slot = 0;
    return m_IDs.direct(id, slot) ? static_cast<int>(slot) : -1;
  }
};

std::string first_line(const std::string& what) {
  const std::size_t start = what.find("Message:");
  std::string line = start == std::string::npos ? what : what.substr(start + 8);
  line = line.substr(0, line.find('\n'));
  const std::size_t first = line.find_first_not_of(' ');
  return first == std::string::npos ? "" : line.substr(first);
}

class Ekf6dRun final : public AlgorithmRun {
 public:
  Ekf6dRun(const Ekf6dOptions& options, const RangeBearingSensor& sensor, const LandmarkTruth& truth,
           const std::filesystem::path& dir)
      : options_(options),
        sensor_(sensor),
        dir_(dir),
        scorer_(truth),
        iterations_(dir / "iterations.csv", {}),
        trajectory_(dir / "trajectory.tum") {
    // Fixed in code and logged with the run (spec mrpt §6.2).
    filter_.KF_options.method = options.method == EkfMethod::Davison ? mrpt::bayes::kfEKFAlaDavison : mrpt::bayes::kfEKFNaive;
    filter_.options.force_ignore_odometry = true;  // belt and braces: the actions are empty anyway
    filter_.options.std_sensor_range = static_cast<float>(options.std_range);
    filter_.options.std_sensor_yaw = static_cast<float>(options.std_yaw_rad);
    filter_.options.std_sensor_pitch = static_cast<float>(options.std_pitch_rad);
    filter_.options.stds_Q_no_odo.resize(7);
    for (int i = 0; i < 7; ++i) filter_.options.stds_Q_no_odo[i] = static_cast<float>(options.stds_q[i]);
    filter_.options.data_assoc_method = options.association == EkfAssociation::Nn ? mrpt::slam::assocNN : mrpt::slam::assocJCBB;
    filter_.options.data_assoc_IC_chi2_thres = options.chi2_threshold;
    filter_.setMinLoggingLevel(mrpt::system::LVL_ERROR);  // not a warning per missed prediction
  }

  const std::string& name() const override { return name_; }

  void step(const ObservationFrame& observation, const TruthFrame& truth) override {
    digest_.add(observation);
    if (!status_.empty()) return;  // failed or stopped: the rest of the stream is not processed
    const int k = observation.iteration;
    // Known association: every row carries its true id; otherwise none does (never mixed,
    // spec mrpt §1.8 item 4).
    static const std::vector<int> unknown;
    const std::vector<int>& ids = options_.association == EkfAssociation::Known ? truth.landmark_ids : unknown;
    mrpt::obs::CSensoryFrame::Ptr sf = std::make_shared<mrpt::obs::CSensoryFrame>();
    sf->insert(bearing_range_observation(observation, ids, sensor_, 1.0e9 + k));
    mrpt::obs::CActionCollection::Ptr no_odometry = std::make_shared<mrpt::obs::CActionCollection>();  // never null (§1.8 item 2)

    const std::size_t before = filter_.getNumberOfLandmarksInTheMap();
    const auto start = std::chrono::steady_clock::now();
    try {
      filter_.processActionObservation(no_odometry, sf);
    } catch (const std::exception& e) {
      status_ = "failed at iteration " + std::to_string(k) + ": " + first_line(e.what());
      return;
    }
    const double runtime_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

    // Scoring, outside the timed region.
    const Rigid3 pose = robot_axes_from_mrpt(mrpt_pose());
    const std::size_t n = filter_.getNumberOfLandmarksInTheMap();
    map_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      CRangeBearingKFSLAM::KFArray_FEAT mean;
      filter_.getLandmarkMean(i, mean);
      map_[i] = robot_from_mrpt(Eigen::Vector3d(mean[0], mean[1], mean[2]));
    }
    if (!pose.translation.allFinite() || !pose.rotation.allFinite() ||
        std::any_of(map_.begin(), map_.end(), [](const Eigen::Vector3d& p) { return !p.allFinite(); })) {
      status_ = "failed at iteration " + std::to_string(k) + ": the filter state became NaN";
      return;
    }
    scorer_.associate(assignment(observation.points.size(), before, truth.landmark_ids), truth.landmark_ids);
    all_ids_.resize(n);
    for (std::size_t i = 0; i < n; ++i) all_ids_[i] = static_cast<int>(i);  // an EKF update moves every landmark
    const IterationScore s = scorer_.score(k, pose, truth, all_ids_, [&](int id) { return std::optional(map_[id]); }, runtime_ms);
    iterations_.row(k, s, runtime_ms, observation.points.size());
    trajectory_.write(static_cast<double>(k), pose);

    over_budget_ = runtime_ms > options_.time_budget_ms ? over_budget_ + 1 : 0;
    if (over_budget_ >= options_.budget_iterations)
      status_ = "stopped at iteration " + std::to_string(k) + ": over the time budget (" +
                std::to_string(static_cast<int>(options_.time_budget_ms)) + " ms) for " +
                std::to_string(options_.budget_iterations) + " iterations";
  }

  SummaryRow finish() override {
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

  SummaryRow summary_over(int iterations) const override {
    SummaryRow row;
    row.algorithm = name_;
    row.status = status_.empty() ? "ok" : status_;
    scorer_.fill(row, static_cast<std::size_t>(iterations));
    row.input_digest = digest_.hex();
    return row;
  }

 private:
  Rigid3 mrpt_pose() const {
    const mrpt::poses::CPose3DQuat q = filter_.getCurrentRobotPoseMean();
    const Eigen::Quaterniond rotation(q.quat().r(), q.quat().x(), q.quat().y(), q.quat().z());
    return Rigid3::from(rotation, {q.x(), q.y(), q.z()});
  }

  // Map index of each observation row. Known association: the filter's own id table. Otherwise
  // its data association; rows it left unassociated became new landmarks, appended in row order
  // (CKalmanFilterCapable's "add new landmarks" step).
  std::vector<int> assignment(std::size_t rows, std::size_t before, const std::vector<int>& true_ids) {
    std::vector<int> out(rows, -1);
    if (options_.association == EkfAssociation::Known) {
      for (std::size_t r = 0; r < rows; ++r) out[r] = filter_.slot_of(true_ids[r]);
      return out;
    }
    for (const auto& [row, index] : filter_.getLastDataAssociation().results.associations) out[row] = static_cast<int>(index);
    std::size_t next = before;
    for (std::size_t r = 0; r < rows; ++r)
      if (out[r] < 0) out[r] = static_cast<int>(next++);
    return out;
  }

  std::string name_ = "ekf6d";
  Ekf6dOptions options_;
  RangeBearingSensor sensor_;
  std::filesystem::path dir_;
  Filter filter_;
  RunScorer scorer_;
  IterationTable iterations_;
  TumWriter trajectory_;
  std::vector<Eigen::Vector3d> map_;
  std::vector<int> all_ids_;
  int over_budget_ = 0;
  std::string status_;
  FrameDigest digest_;
};

}  // namespace

std::unique_ptr<AlgorithmRun> make_ekf6d_run(const Ekf6dOptions& options, const RangeBearingSensor& sensor,
                                             const LandmarkTruth& truth, const std::filesystem::path& dir) {
  return std::make_unique<Ekf6dRun>(options, sensor, truth, dir);
}

}  // namespace relslam::eval
