#include "relslam/point/turn_rate.hpp"

#include <Eigen/Geometry>

namespace relslam::point {

void TurnRate::record(int k, const Eigen::Matrix3d& world_R_robot) {
  if (window_ <= 0) return;
  records_.emplace_back(k, world_R_robot);
  // Keep the oldest record that still leaves the span at least `window` iterations.
  while (records_.size() > 2 && records_[1].first <= k - window_) records_.pop_front();
  const auto& [k0, r0] = records_.front();
  if (k - k0 < window_) return;  // too short a span: the rate stays as it was
  const Eigen::AngleAxisd turned(r0.transpose() * world_R_robot);
  rate_ = turned.angle() * turned.axis() / static_cast<double>(k - k0);
}

Eigen::Matrix3d TurnRate::turn(int from, int to) const {
  const Eigen::Vector3d angle = rate_ * static_cast<double>(to - from);
  const double norm = angle.norm();
  if (!(norm > 0)) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(norm, angle / norm).toRotationMatrix();
}

void TurnRate::clear() {
  records_.clear();
  rate_.setZero();
}

}  // namespace relslam::point
