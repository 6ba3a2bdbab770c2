#pragma once
// Internal to the algorithms layer: an MRPT range-bearing KF-SLAM filter that notes, each step,
// what the divergence check reads (relslam/eval/algorithms/filter_divergence.hpp): the
// normalised innovation squared of the observations it associated to its map, and how far its
// update moved the pose from the prediction. MRPT computes the innovation covariance
// S = H P H' + R of every predicted landmark before its data association; the hook after that
// association sees S, the predictions, the observations and the predicted state together.

#include "relslam/eval/algorithms/filter_divergence.hpp"

#include <Eigen/Cholesky>

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace relslam::eval {

template <class Filter>
class InnovationWatch : public Filter {
 public:
  using typename Filter::KFArray_OBS;
  using typename Filter::KFMatrix;
  using typename Filter::KFMatrix_OxO;
  using typename Filter::vector_KFArray_OBS;
  static constexpr std::size_t kObs = Filter::get_observation_size();
  static constexpr int kPosition = Filter::get_vehicle_size() == 3 ? 2 : 3;  // x, y (2D) or x, y, z (6D)

  // After a step: its innovations, and the update's move of the position from the prediction in
  // standard deviations of the prediction (0 when the prediction had no uncertainty to measure
  // it by: the first step, whose pose is the map frame).
  StepInnovation step() const {
    StepInnovation out = innovation_;
    if (predicted_.size() != kPosition) return out;
    const Eigen::VectorXd moved = Eigen::Map<const Eigen::VectorXd>(&this->m_xkk[0], kPosition) - predicted_;
    const Eigen::LLT<Eigen::MatrixXd> llt(predicted_cov_);
    if (llt.info() == Eigen::Success && predicted_cov_.diagonal().minCoeff() > 0)
      out.pose_jump_sigma = std::sqrt(moved.dot(llt.solve(moved)));
    return out;
  }

 protected:
  // MRPT calls this once per step, or again with more predicted landmarks when its guess of the
  // landmarks in view missed one; the last call's association is the one the update uses.
  void OnGetObservationsAndDataAssociation(vector_KFArray_OBS& out_z, std::vector<int>& out_data_association,
                                           const vector_KFArray_OBS& in_all_predictions, const KFMatrix& in_S,
                                           const std::vector<size_t>& in_lm_indices_in_S,
                                           const KFMatrix_OxO& in_R) override {
    Filter::OnGetObservationsAndDataAssociation(out_z, out_data_association, in_all_predictions, in_S,
                                                in_lm_indices_in_S, in_R);
    innovation_ = {};
    predicted_ = Eigen::Map<const Eigen::VectorXd>(&this->m_xkk[0], kPosition);
    predicted_cov_ = this->m_pkk.asEigen().block(0, 0, kPosition, kPosition);
    for (std::size_t row = 0; row < out_data_association.size(); ++row) {
      const int slot = out_data_association[row];
      if (slot < 0) continue;  // a new landmark: no prediction to compare with
      std::size_t in_s = 0;
      while (in_s < in_lm_indices_in_S.size() && in_lm_indices_in_S[in_s] != static_cast<std::size_t>(slot)) ++in_s;
      if (in_s == in_lm_indices_in_S.size()) continue;  // MRPT calls again with it predicted
      add(out_z[row], in_all_predictions[slot], in_S.asEigen().block(kObs * in_s, kObs * in_s, kObs, kObs));
    }
  }

 private:
  void add(const KFArray_OBS& z, const KFArray_OBS& prediction, const Eigen::MatrixXd& s) {
    KFArray_OBS nu = z;
    this->OnSubstractObservationVectors(nu, prediction);  // wraps the angles
    const Eigen::VectorXd v = nu.asEigen().template cast<double>();
    const Eigen::LLT<Eigen::MatrixXd> llt(s);
    innovation_.nis += llt.info() == Eigen::Success ? v.dot(llt.solve(v)) : std::numeric_limits<double>::quiet_NaN();
    innovation_.dof += static_cast<int>(kObs);
  }

  StepInnovation innovation_;
  Eigen::VectorXd predicted_;      // the position after the motion model, before the update
  Eigen::MatrixXd predicted_cov_;  // ...and its covariance
};

}  // namespace relslam::eval
