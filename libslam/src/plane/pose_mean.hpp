#pragma once
// The mean of several planar poses (A27): translations averaged, headings by their
// circular mean atan2(Σ sin, Σ cos). Used by RltPlaneCompare, BuildMap and GetPoset alike.

#include "relslam/core/planar_pose.hpp"

#include <Eigen/Core>

#include <cmath>

namespace relslam::plane {

class PoseMean {
 public:
  void add(const PlanarPose& pose) { add(pose.translation, std::cos(pose.heading), std::sin(pose.heading)); }
  // A heading given as (cos, sin) of a unit vector — no trigonometry needed.
  void add(const Eigen::Vector2d& translation, double cos_heading, double sin_heading) {
    translation_ += translation;
    cos_ += cos_heading;
    sin_ += sin_heading;
    ++count_;
  }
  int count() const { return count_; }
  // The identity while empty.
  PlanarPose mean() const {
    if (count_ == 0) return {};
    return {translation_ / count_, wrap_angle(std::atan2(sin_, cos_))};
  }

 private:
  Eigen::Vector2d translation_ = Eigen::Vector2d::Zero();
  double cos_ = 0;
  double sin_ = 0;
  int count_ = 0;
};

}  // namespace relslam::plane
