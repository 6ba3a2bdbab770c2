// MRPT's 6D range-bearing EKF-SLAM (CRangeBearingKFSLAM) as one algorithm of a run: the
// thesis's baseline (6.7), driven so as to avoid MRPT 2.5.8's traps.
#include "ekf6d.hpp"

#include "innovation_watch.hpp"
#include "mrpt_filter.hpp"
#include "relslam/eval/io/mrpt_observation.hpp"
#include "relslam/eval/io/range_bearing.hpp"

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement3D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <mrpt/poses/CPose3DQuat.h>
#include <mrpt/slam/CRangeBearingKFSLAM.h>

#include <Eigen/Geometry>

namespace relslam::eval {
namespace {

using mrpt::slam::CRangeBearingKFSLAM;

// The filter with its landmark-id table readable: with known association that table is the
// authority on which state slot holds which landmark (MRPT keeps it protected).
class Filter final : public InnovationWatch<CRangeBearingKFSLAM> {
 public:
  // State slot of landmark `id`, -1 when the filter has not added it.
  int slot_of(int id) const {
    unsigned int slot = 0;
    return m_IDs.direct(id, slot) ? static_cast<int>(slot) : -1;
  }
};

class Ekf6d final : public MrptFilter {
 public:
  Ekf6d(const Ekf6dOptions& options, const RangeBearingSensor& sensor)
      : MrptFilter("ekf6d", {options.time_budget_ms, options.budget_iterations}, options.divergence),
        options_(options),
        sensor_(sensor) {
    // Fixed in code and logged with the run.
    filter_.KF_options.method =
        options.method == EkfMethod::Davison ? mrpt::bayes::kfEKFAlaDavison : mrpt::bayes::kfEKFNaive;
    // Without use_odometry the actions are empty anyway; the flag is belt and braces.
    filter_.options.force_ignore_odometry = !options.use_odometry;
    filter_.options.std_sensor_range = static_cast<float>(options.std_range);
    filter_.options.std_sensor_yaw = static_cast<float>(options.std_yaw_rad);
    filter_.options.std_sensor_pitch = static_cast<float>(options.std_pitch_rad);
    filter_.options.stds_Q_no_odo.resize(7);
    for (int i = 0; i < 7; ++i) filter_.options.stds_Q_no_odo[i] = static_cast<float>(options.stds_q[i]);
    filter_.options.data_assoc_method =
        options.association == EkfAssociation::Nn ? mrpt::slam::assocNN : mrpt::slam::assocJCBB;
    filter_.options.data_assoc_IC_chi2_thres = options.chi2_threshold;
    filter_.setMinLoggingLevel(mrpt::system::LVL_ERROR);  // not a warning per missed prediction
  }

 private:
  void process(const ObservationFrame& observation, const TruthFrame& truth) override {
    // Known association: every row carries its true id; otherwise none does (never mixed,
    // see above).
    static const std::vector<int> unknown;
    const std::vector<int>& ids = options_.association == EkfAssociation::Known ? truth.landmark_ids : unknown;
    mrpt::obs::CSensoryFrame::Ptr sf = std::make_shared<mrpt::obs::CSensoryFrame>();
    sf->insert(bearing_range_observation(observation, ids, sensor_, 1.0e9 + observation.iteration));
    mrpt::obs::CActionCollection::Ptr actions = std::make_shared<mrpt::obs::CActionCollection>();  // never null
    // A frame without odometry (the first) leaves the filter its constant-position model.
    if (options_.use_odometry && observation.odometry) actions->insert(odometry_action(*observation.odometry));
    filter_.processActionObservation(actions, sf);
  }

  // The frame's odometry as kf-slam reads a 3D odometry action: the pose increment with a
  // Gaussian of the configured (or the log's) standard deviations, in the increment's frame.
  mrpt::obs::CActionRobotMovement3D odometry_action(const Rigid3& motion) const {
    const Rigid3 m = mrpt_axes_from_robot(motion);
    const Eigen::Quaterniond q(m.rotation);
    const mrpt::poses::CPose3D mean(
        mrpt::poses::CPose3DQuat(m.translation.x(), m.translation.y(), m.translation.z(),
                                 mrpt::math::CQuaternionDouble(q.w(), q.x(), q.y(), q.z())));
    mrpt::math::CMatrixDouble66 cov;
    cov.setZero();
    for (int i = 0; i < 3; ++i) cov(i, i) = options_.odometry_std_xyz * options_.odometry_std_xyz;
    for (int i = 3; i < 6; ++i) cov(i, i) = options_.odometry_std_angle_rad * options_.odometry_std_angle_rad;
    mrpt::obs::CActionRobotMovement3D action;
    action.estimationMethod = mrpt::obs::CActionRobotMovement3D::emOdometry;
    action.rawOdometryIncrementReading = mean;
    action.poseChange = mrpt::poses::CPose3DPDFGaussian(mean, cov);
    return action;
  }

  std::size_t map_size() const override { return filter_.getNumberOfLandmarksInTheMap(); }

  Rigid3 filter_pose() const override {
    const mrpt::poses::CPose3DQuat q = filter_.getCurrentRobotPoseMean();
    const Eigen::Quaterniond rotation(q.quat().r(), q.quat().x(), q.quat().y(), q.quat().z());
    return robot_axes_from_mrpt(Rigid3::from(rotation, {q.x(), q.y(), q.z()}));
  }

  Eigen::Vector3d landmark(std::size_t index) const override {
    CRangeBearingKFSLAM::KFArray_FEAT mean;
    filter_.getLandmarkMean(index, mean);
    return robot_from_mrpt(Eigen::Vector3d(mean[0], mean[1], mean[2]));
  }

  // Known association: the filter's own id table. Otherwise its data association; rows it left
  // unassociated became new landmarks, appended in row order (CKalmanFilterCapable's "add new
  // landmarks" step).
  StepInnovation innovation() const override { return filter_.step(); }

  std::vector<int> slots(std::size_t rows, std::size_t before, const std::vector<int>& true_ids) const override {
    std::vector<int> out(rows, -1);
    if (options_.association == EkfAssociation::Known) {
      for (std::size_t r = 0; r < rows; ++r) out[r] = filter_.slot_of(true_ids[r]);
      return out;
    }
    return unknown_association_slots(filter_.getLastDataAssociation().results.associations, rows, before);
  }

  Ekf6dOptions options_;
  RangeBearingSensor sensor_;
  Filter filter_;
};

}  // namespace

std::unique_ptr<Algorithm> make_ekf6d(const Ekf6dOptions& options, const RangeBearingSensor& sensor) {
  return std::make_unique<Ekf6d>(options, sensor);
}

}  // namespace relslam::eval
