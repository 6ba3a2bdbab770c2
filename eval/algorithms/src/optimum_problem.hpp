#pragma once
// Internal to the algorithms layer: the batch optimum's least-squares problem and its Ceres
// solve (docs/batch_optimum.md). Every pose and every landmark are unknowns; each observation
// of a landmark with a known id is one residual under the sensor's noise model, each frame's
// odometry (when used) one relative-pose residual; the first pose is held (the gauge).

#include "relslam/core/rigid.hpp"
#include "relslam/eval/config/batch_optimum_options.hpp"
#include "relslam/eval/io/range_bearing.hpp"

#include <optional>
#include <string>
#include <vector>

namespace relslam::eval {

// One observation: landmark `landmark` seen at `p_robot` (the robot frame) from pose `pose`.
struct OptimumObservation {
  int pose = 0;
  int landmark = 0;
  Eigen::Vector3d p_robot;
};

// previous_T_current between poses k-1 and k with its standard deviations per step: a frame's
// odometry, or the EKF's constant-position motion model (the identity).
struct StepMeasurement {
  Rigid3 previous_T_current;
  double std_xyz = 1;        // units, per axis
  double std_angle_rad = 1;  // per axis
};

// A smooth path's prior: the step from pose k-1 to k (previous_T_current) the same as the one
// from k-2 to k-1, with these standard deviations of the difference per step.
struct ConstantVelocity {
  double std_xyz = 1;        // units, per axis
  double std_angle_rad = 1;  // per axis
};

struct OptimumProblem {
  std::vector<Rigid3> world_T_robot;       // the start, solved in place; [0] held
  std::vector<Eigen::Vector3d> landmarks;  // the start, solved in place
  std::vector<OptimumObservation> observations;
  // steps[k]: between poses k-1 and k (k >= 1), when there is one.
  std::vector<std::optional<StepMeasurement>> steps;
  // With a value: the constant-velocity prior on every three consecutive poses whose two steps
  // have no measurement in steps.
  std::optional<ConstantVelocity> constant_velocity;
};

struct OptimumReport {
  bool usable = false;       // Ceres's solution is usable (a converged or stopped-at-the-cap solve)
  int solver_iterations = 0;
  double initial_cost = 0, final_cost = 0;  // half the sum of squared whitened residuals (under the loss)
  double solve_s = 0;                       // wall time of the solve, seconds
  std::string termination;                  // Ceres's own words on why it stopped
};

// The noise model the observations are whitened with: range, yaw and pitch (MRPT's spherical
// measurement, range_bearing.hpp) when the sensor gives range and yaw standard deviations (a
// rawlog's sensor; a planar one's pitch deviation is its yaw's); otherwise white Gaussian noise per axis of std_range (the simulator's,
// sim::SimOptions::noise_sigma; 1 when it gives none: noise-free data weighs nothing).
struct ObservationNoise {
  bool spherical = false;
  double std_range = 1, std_yaw_rad = 1, std_pitch_rad = 1;  // std_range is per axis when not spherical
};
ObservationNoise observation_noise(const RangeBearingSensor& sensor);

// Solves `problem` in place with Ceres (Levenberg-Marquardt on the sparse normal equations, one
// thread: deterministic).
OptimumReport solve_optimum(OptimumProblem& problem, const ObservationNoise& noise, const BatchOptimumOptions& options);

}  // namespace relslam::eval
