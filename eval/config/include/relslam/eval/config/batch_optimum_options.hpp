#pragma once
// Settings of the batch optimum (algorithm batch_optimum, docs/batch_optimum.md): the full
// nonlinear least-squares solution over every pose and every landmark, solved once after the
// last frame, the accuracy floor beside the online estimators (beyond the thesis). describe()
// gives each field's key, help and checks (relslam/core/option_fields.hpp).

#include "relslam/core/option_fields.hpp"

#include <numbers>
#include <optional>
#include <string_view>

namespace relslam::eval {

// Where the solve starts from. Least squares with the right noise model has one minimum near
// the truth; the start only has to lie in its basin.
enum class OptimumStart {
  Truth,          // the true poses, perturbed (seeded from the scenario's seed) [C]
  RelativePoint,  // the poses of a Relative Point run over the same frames (its settings)
};
inline constexpr OptimumStart kOptimumStarts[] = {OptimumStart::Truth, OptimumStart::RelativePoint};
inline std::string_view to_string(OptimumStart start) {
  return start == OptimumStart::Truth ? "truth" : "relative_point";
}

// Where the sensor model comes from: the run's own (the sensor's stated noise), or the EKF's
// settings, to give the floor exactly what the EKF is given.
enum class OptimumModel {
  Own,    // the sensor's stated noise [C]
  Ekf6d,  // the EKF's sensor model (ekf6d.std_range, std_yaw_deg, std_pitch_deg)
};
inline constexpr OptimumModel kOptimumModels[] = {OptimumModel::Own, OptimumModel::Ekf6d};
inline std::string_view to_string(OptimumModel model) { return model == OptimumModel::Own ? "own" : "ekf6d"; }

// A motion model between frames without odometry: none, the EKF's, or a smooth path's.
enum class OptimumMotion {
  Own,               // none, as Relative Point (the thesis's comparison) [C]
  Ekf6d,             // the EKF's constant position: the pose stays, with ekf6d.stds_q per step
  ConstantVelocity,  // each step's motion (previous_T_current) as the step's before it
};
inline constexpr OptimumMotion kOptimumMotions[] = {OptimumMotion::Own, OptimumMotion::Ekf6d,
                                                    OptimumMotion::ConstantVelocity};
inline std::string_view to_string(OptimumMotion motion) {
  return motion == OptimumMotion::Own ? "own" : motion == OptimumMotion::Ekf6d ? "ekf6d" : "constant_velocity";
}

// Which landmark each observation is: the ids the frames carry (a simulation's truth, a rawlog's
// own), or the landmarks a Relative Point run over the same frames assigns them to, for data
// without ids (Victoria Park's trees). Relative Point's merges (thesis 6.5.2) are followed to the
// point kept, and the observations of points it flags dynamic (6.5.3) are left out.
enum class OptimumAssociation {
  Known,          // the frames' ids; observations without one are left out [C]
  RelativePoint,  // a Relative Point run's assignment (its settings)
};
inline constexpr OptimumAssociation kOptimumAssociations[] = {OptimumAssociation::Known,
                                                              OptimumAssociation::RelativePoint};
inline std::string_view to_string(OptimumAssociation association) {
  return association == OptimumAssociation::Known ? "known" : "relative_point";
}

// The loss on each observation's whitened residual. With the right association and Gaussian
// noise least squares (none) is the maximum-likelihood estimate; with an association taken from
// another estimator (association relative_point) a wrong match or a split landmark is an outlier
// that a robust loss lets go [C].
enum class OptimumLoss {
  Auto,    // none with the known association, cauchy with relative_point's [C, measured]
  None,    // least squares
  Huber,   // quadratic up to loss_scale sigmas, linear beyond
  Cauchy,  // log(1 + (r / loss_scale)^2): an outlier's pull fades
};
inline constexpr OptimumLoss kOptimumLosses[] = {OptimumLoss::Auto, OptimumLoss::None, OptimumLoss::Huber,
                                                 OptimumLoss::Cauchy};
inline std::string_view to_string(OptimumLoss loss) {
  switch (loss) {
    case OptimumLoss::Auto: return "auto";
    case OptimumLoss::None: return "none";
    case OptimumLoss::Huber: return "huber";
    case OptimumLoss::Cauchy: break;
  }
  return "cauchy";
}

struct BatchOptimumOptions {
  OptimumStart start = OptimumStart::Truth;
  OptimumAssociation association = OptimumAssociation::Known;
  // The perturbation of every true pose but the first (the gauge), per axis: large against the
  // sensor noise of the shipped scenarios (0.1 units), so the solve, not the start, sets the
  // result [C].
  double start_sigma_position = 0.5;                             // units
  double start_sigma_rotation_rad = 2.0 * std::numbers::pi / 180.0;  // read and written in degrees
  // Use the frames' odometry as a relative-pose measurement between consecutive poses, as
  // ekf6d.use_odometry feeds it to the EKF; off by default, the thesis's comparison without
  // odometry [T]. Its standard deviations per step, as the EKF's.
  bool use_odometry = false;
  double odometry_std_xyz = 0.05;                                  // units per step [C]
  double odometry_std_angle_rad = 0.5 * std::numbers::pi / 180.0;  // read and written in degrees [C]
  // The observations' noise model: the sensor's (own) or the EKF's sensor model (ekf6d) [C].
  OptimumModel noise_model = OptimumModel::Own;
  // A motion model between consecutive frames without odometry: none (own), the EKF's
  // constant-position model (ekf6d: the pose stays, with ekf6d.stds_q per step) or constant
  // velocity (each step's motion as the one before, with the deviations below) [C].
  OptimumMotion motion_model = OptimumMotion::Own;
  // Constant velocity: how much a step's motion may differ from the one before, per axis. The
  // simulated figure eight moves 0.3 units a step at constant speed, turning by about 0.3 degrees
  // a step on its arcs and not at all on its straights: the change where they meet [C].
  double velocity_std_xyz = 0.01;                                  // units per step, per axis
  double velocity_std_angle_rad = 0.3 * std::numbers::pi / 180.0;  // read and written in degrees
  // The observations' loss and its scale in sigmas of the whitened residual (each component's
  // deviation over its standard deviation; the loss sees the squared norm of the three). Scale 1
  // gave the lowest error with Relative Point's association on MRPT's 6D demo log and both
  // Victoria Park windows among 1, 2 and 3 (docs/algorithms/batch-optimum.md) [C, measured].
  OptimumLoss loss = OptimumLoss::Auto;
  double loss_scale = 1.0;
  // Levenberg-Marquardt iterations at most; a consistent start converges in a handful [C].
  int max_iterations = 100;
};

// The scenario keys of BatchOptimumOptions (batch_optimum.*).
void describe(OptionsOf<BatchOptimumOptions> auto& o, auto& f) {
  f.choice("start", o.start, "start of the solve: truth (perturbed, seeded) or relative_point (its run's poses)",
           kOptimumStarts);
  f.choice("association", o.association,
           "landmark of each observation: known (the frames' ids) or relative_point (a Relative Point run's "
           "assignment, for data without ids)",
           kOptimumAssociations);
  // Bounded above so that a typo cannot start the solve beyond where it may diverge to [C].
  f.field("start_sigma_position", o.start_sigma_position, "start truth: perturbation of each pose per axis, units",
          at_least(0.0), at_most(1e6));
  f.degrees("start_sigma_rotation_deg", o.start_sigma_rotation_rad,
            "start truth: perturbation of each pose's rotation per axis", at_least(0.0), at_most(180.0));
  f.field("use_odometry", o.use_odometry, "add the frames' odometry as relative-pose measurements");
  f.field("odometry_std_xyz", o.odometry_std_xyz, "odometry std. deviation per step, units", above(0.0));
  f.degrees("odometry_std_angle_deg", o.odometry_std_angle_rad, "odometry rotation std. deviation per step",
            above(0.0));
  f.choice("noise_model", o.noise_model,
           "observation noise: own (the sensor's) or ekf6d (the EKF's std_range, std_yaw_deg, std_pitch_deg)",
           kOptimumModels);
  f.choice("motion_model", o.motion_model,
           "between frames without odometry: own (none), ekf6d (the EKF's constant position, stds_q) or "
           "constant_velocity",
           kOptimumMotions);
  f.field("velocity_std_xyz", o.velocity_std_xyz,
          "constant_velocity: std. deviation of a step's change of translation per axis, units", above(0.0));
  f.degrees("velocity_std_angle_deg", o.velocity_std_angle_rad,
            "constant_velocity: std. deviation of a step's change of rotation per axis", above(0.0));
  f.choice("loss", o.loss,
           "loss on each observation: auto (none with known ids, cauchy with association relative_point), none, "
           "huber or cauchy",
           kOptimumLosses);
  f.field("loss_scale", o.loss_scale, "scale of the huber or cauchy loss, sigmas of the whitened residual",
          above(0.0));
  f.field("max_iterations", o.max_iterations, "Levenberg-Marquardt iterations at most", at_least(1));
}

}  // namespace relslam::eval
