#pragma once
// The robot's 6D motion along a centre line, expressed in the world frame. Part of relslam/sim.

#include "relslam/core/rigid.hpp"
#include "relslam/sim/centerline.hpp"
#include "relslam/sim/options.hpp"

#include <memory>

namespace relslam::sim {

// Invariant: world_T_robot(0) is exactly the identity. Everything built on the path is moved
// by the inverse of the start pose, so truth, the relative map (anchored to the
// first observations, thesis 6.3.3) and the EKF map (its frame is the first robot pose) all
// share one frame and need no alignment.
class Path {
 public:
  explicit Path(const SimOptions& options);
  Path(Path&&) noexcept;
  Path& operator=(Path&&) noexcept;
  ~Path();

  int iterations() const { return iterations_; }
  // Arc length advanced per iteration: constant speed.
  double step_length() const { return step_; }
  // Arc length at iteration k (wrapped for loops; 0 for a stationary robot).
  double arc_length(int k) const;
  Rigid3 world_T_robot(int k) const;

  // The centre line the point band follows, in the world frame.
  double field_length() const { return field_length_; }
  CenterlinePoint centerline(double s) const;

 private:
  Rigid3 design_T_robot(double s) const;

  std::unique_ptr<Centerline> line_;
  PathKind kind_;
  bool wobble_;
  int iterations_;
  double step_;
  double field_length_;
  Rigid3 world_T_design_;
};

}  // namespace relslam::sim
