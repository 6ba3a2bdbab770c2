#pragma once
// Deviation (adaptive preset): the robot's turn rate, measured from the rotations of
// the poses whose registration fixed the rotation, to predict the rotation of an iteration
// whose registration cannot (one point in view). Eigen only.

#include <Eigen/Core>

#include <deque>
#include <utility>

namespace relslam::point {

// The thesis computes every pose from scratch (6.1) and has no motion model; with one point in
// view a pose's rotation is not observed at all. A robot that turns at a steady rate (the
// figure eight's arcs turn by a constant angle per iteration) keeps turning while one point is
// in view, so its rotation there is the latest one turned on at the rate of the last `window`
// iterations. The rate is the rotation between the oldest and the newest recorded rotation at
// least `window` iterations apart, per iteration, in the robot frame (body rate): a single
// registration's rotation carries a whole observation's noise, and spread over `window`
// iterations it shrinks by that factor.
class TurnRate {
 public:
  // window <= 0: no rate (turn() is the identity).
  explicit TurnRate(int window) : window_(window) {}

  // A rotation observed at iteration k (after every earlier one).
  void record(int k, const Eigen::Matrix3d& world_R_robot);
  // The rotation the robot makes from iteration `from` to `to` at the measured rate, in the robot
  // frame at `from` (world_R(to) = world_R(from) * turn(from, to)); the identity before the
  // records span `window` iterations.
  Eigen::Matrix3d turn(int from, int to) const;
  // Forgets the records (the map frame moved).
  void clear();
  // The measured rate: a rotation vector per iteration in the robot frame.
  const Eigen::Vector3d& rate() const { return rate_; }

 private:
  int window_ = 0;
  std::deque<std::pair<int, Eigen::Matrix3d>> records_;  // oldest first
  Eigen::Vector3d rate_ = Eigen::Vector3d::Zero();
};

}  // namespace relslam::point
