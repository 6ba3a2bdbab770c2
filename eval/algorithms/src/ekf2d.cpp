// MRPT's planar range-bearing EKF-SLAM (CRangeBearingKFSLAM2D): the Victoria Park reference,
// with the vehicle's dead reckoning as odometry or, like the Relative algorithms, without.
#include "ekf2d.hpp"

#include "innovation_watch.hpp"
#include "mrpt_filter.hpp"
#include "relslam/eval/io/mrpt_observation.hpp"
#include "relslam/eval/io/range_bearing.hpp"

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/slam/CRangeBearingKFSLAM2D.h>

#include <cmath>

namespace relslam::eval {
namespace {

using mrpt::slam::CRangeBearingKFSLAM2D;

class Ekf2d final : public MrptFilter {
 public:
  Ekf2d(const Ekf2dOptions& options, const std::string& name, bool use_odometry, const RangeBearingSensor& sensor)
      : MrptFilter(name, {options.time_budget_ms, options.budget_iterations}, options.divergence),
        options_(options),
        use_odometry_(use_odometry),
        association_(use_odometry ? options.association : options.association_no_odometry),
        sensor_(sensor) {
    filter_.KF_options.method =
        options.method == EkfMethod::Davison ? mrpt::bayes::kfEKFAlaDavison : mrpt::bayes::kfEKFNaive;
    filter_.options.std_sensor_range = static_cast<float>(options.std_range);
    filter_.options.std_sensor_yaw = static_cast<float>(options.std_yaw_rad);
    filter_.options.stds_Q_no_odo.resize(3);
    for (int i = 0; i < 3; ++i) filter_.options.stds_Q_no_odo[i] = static_cast<float>(options.stds_q_no_odometry[i]);
    filter_.options.data_assoc_method =
        association_ == EkfAssociation::Nn ? mrpt::slam::assocNN : mrpt::slam::assocJCBB;
    filter_.options.data_assoc_IC_chi2_thres = options.chi2_threshold;
    filter_.setMinLoggingLevel(mrpt::system::LVL_ERROR);
  }

 private:
  void process(const ObservationFrame& observation, const TruthFrame& truth) override {
    static const std::vector<int> unknown;
    const std::vector<int>& ids = association_ == EkfAssociation::Known ? truth.landmark_ids : unknown;
    mrpt::obs::CSensoryFrame::Ptr sf = std::make_shared<mrpt::obs::CSensoryFrame>();
    sf->insert(bearing_range_observation(observation, ids, sensor_, 1.0e9 + observation.iteration));
    mrpt::obs::CActionCollection::Ptr actions = std::make_shared<mrpt::obs::CActionCollection>();  // never null
    if (use_odometry_ && observation.odometry) actions->insert(odometry_action(*observation.odometry));
    filter_.processActionObservation(actions, sf);
  }

  // The frame's odometry as MRPT's 2D odometry action, with a Gaussian that grows with the motion.
  mrpt::obs::CActionRobotMovement2D odometry_action(const Rigid3& motion) const {
    const Pose2 m = planar_from_robot_pose(motion);
    const double xy = options_.odometry_std_xy + options_.odometry_std_xy_ratio * std::hypot(m.x, m.y);
    const double heading =
        options_.odometry_std_heading_rad + options_.odometry_std_heading_ratio * std::abs(m.heading);
    mrpt::math::CMatrixDouble33 cov;
    cov.setZero();
    cov(0, 0) = cov(1, 1) = xy * xy;
    cov(2, 2) = heading * heading;
    mrpt::obs::CActionRobotMovement2D action;
    action.estimationMethod = mrpt::obs::CActionRobotMovement2D::emOdometry;
    action.rawOdometryIncrementReading = mrpt::poses::CPose2D(m.x, m.y, m.heading);
    action.poseChange = std::make_shared<mrpt::poses::CPosePDFGaussian>(action.rawOdometryIncrementReading, cov);
    return action;
  }

  std::size_t map_size() const override { return filter_.getNumberOfLandmarksInTheMap(); }

  Rigid3 filter_pose() const override {
    mrpt::poses::CPosePDFGaussian p;
    filter_.getCurrentRobotPose(p);
    return robot_pose_from_planar({p.mean.x(), p.mean.y(), p.mean.phi()});
  }

  Eigen::Vector3d landmark(std::size_t index) const override {
    CRangeBearingKFSLAM2D::KFArray_FEAT mean;
    filter_.getLandmarkMean(index, mean);
    return robot_from_mrpt(Eigen::Vector3d(mean[0], mean[1], 0.0));
  }

  StepInnovation innovation() const override { return filter_.step(); }

  std::vector<int> slots(std::size_t rows, std::size_t before, const std::vector<int>&) const override {
    return unknown_association_slots(filter_.getLastDataAssociation().results.associations, rows, before);
  }

  Ekf2dOptions options_;
  bool use_odometry_;
  EkfAssociation association_;
  RangeBearingSensor sensor_;
  InnovationWatch<CRangeBearingKFSLAM2D> filter_;
};

}  // namespace

std::unique_ptr<Algorithm> make_ekf2d(const Ekf2dOptions& options, const std::string& name, bool use_odometry,
                                      const RangeBearingSensor& sensor) {
  return std::make_unique<Ekf2d>(options, name, use_odometry, sensor);
}

}  // namespace relslam::eval
