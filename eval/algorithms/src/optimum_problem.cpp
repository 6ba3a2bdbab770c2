#include "optimum_problem.hpp"

#include "relslam/relax/ceres_relaxation.hpp"

#include <ceres/ceres.h>

#include <array>
#include <chrono>
#include <memory>

namespace relslam::eval {
namespace {

// A pose's parameters: the quaternion (x, y, z, w: Eigen's storage order, as
// EigenQuaternionManifold expects) and the translation of world_T_robot.
struct PoseBlock {
  std::array<double, 4> q;
  std::array<double, 3> t;
};

template <typename T>
Eigen::Matrix<T, 3, 1> robot_from_world(const T* q, const T* t, const T* landmark) {
  const Eigen::Map<const Eigen::Quaternion<T>> rotation(q);
  const Eigen::Map<const Eigen::Matrix<T, 3, 1>> translation(t), l(landmark);
  return rotation.conjugate() * (l - translation);
}

// White Gaussian noise per axis of the robot frame: the simulator's sensor.
struct CartesianResidual {
  Eigen::Vector3d z;
  double inverse_sigma;

  template <typename T>
  bool operator()(const T* q, const T* t, const T* landmark, T* residual) const {
    Eigen::Map<Eigen::Matrix<T, 3, 1>> r(residual);
    r = T(inverse_sigma) * (robot_from_world(q, t, landmark) - z.cast<T>());
    return true;
  }
};

// Range, yaw and pitch in MRPT's sensor axes (range_bearing.hpp): a rawlog's sensor model.
struct SphericalResidual {
  RangeBearing z;
  ObservationNoise noise;

  template <typename T>
  bool operator()(const T* q, const T* t, const T* landmark, T* residual) const {
    const Eigen::Matrix<T, 3, 1> p = robot_from_world(q, t, landmark);
    const T x = p.z(), y = p.x(), up = p.y();  // mrpt_from_robot
    const T horizontal = ceres::sqrt(x * x + y * y);
    const T range = ceres::sqrt(x * x + y * y + up * up);
    const T yaw_difference = ceres::atan2(y, x) - T(z.yaw_rad);
    residual[0] = (range - T(z.range)) / T(noise.std_range);
    // The yaw difference wrapped to (-pi, pi]: a landmark behind the sensor is not 2 pi off.
    residual[1] = ceres::atan2(ceres::sin(yaw_difference), ceres::cos(yaw_difference)) / T(noise.std_yaw_rad);
    // pitch = -asin(up / range), written as an atan2 that stays smooth at the poles.
    residual[2] = (ceres::atan2(-up, horizontal) - T(z.pitch_rad)) / T(noise.std_pitch_rad);
    return true;
  }
};

// previous_T_current measured (odometry, a motion model) against the two poses' own: translation per axis and
// the rotation's angle-axis (twice the error quaternion's vector part, small angles).
struct OdometryResidual {
  Eigen::Quaterniond q_measured;
  Eigen::Vector3d t_measured;
  double inverse_sigma_xyz, inverse_sigma_angle;

  template <typename T>
  bool operator()(const T* q_a, const T* t_a, const T* q_b, const T* t_b, T* residual) const {
    const Eigen::Map<const Eigen::Quaternion<T>> rotation_a(q_a), rotation_b(q_b);
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> translation_a(t_a), translation_b(t_b);
    const Eigen::Quaternion<T> a_inverse = rotation_a.conjugate();
    const Eigen::Matrix<T, 3, 1> t_relative = a_inverse * (translation_b - translation_a);
    const Eigen::Quaternion<T> q_error = q_measured.cast<T>().conjugate() * (a_inverse * rotation_b);
    Eigen::Map<Eigen::Matrix<T, 6, 1>> r(residual);
    r.template head<3>() = T(inverse_sigma_xyz) * (t_relative - t_measured.cast<T>());
    r.template tail<3>() = T(2.0 * inverse_sigma_angle) * q_error.vec();
    return true;
  }
};

// Two consecutive steps' motions (previous_T_current of poses a->b and b->c) against each other:
// translation per axis and the rotation's angle-axis (small angles), as OdometryResidual with the
// earlier step as the measurement.
struct ConstantVelocityResidual {
  double inverse_sigma_xyz, inverse_sigma_angle;

  template <typename T>
  bool operator()(const T* q_a, const T* t_a, const T* q_b, const T* t_b, const T* q_c, const T* t_c,
                  T* residual) const {
    const Eigen::Map<const Eigen::Quaternion<T>> rotation_a(q_a), rotation_b(q_b), rotation_c(q_c);
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> translation_a(t_a), translation_b(t_b), translation_c(t_c);
    const Eigen::Quaternion<T> q_ab = rotation_a.conjugate() * rotation_b, q_bc = rotation_b.conjugate() * rotation_c;
    const Eigen::Matrix<T, 3, 1> t_ab = rotation_a.conjugate() * (translation_b - translation_a);
    const Eigen::Matrix<T, 3, 1> t_bc = rotation_b.conjugate() * (translation_c - translation_b);
    Eigen::Map<Eigen::Matrix<T, 6, 1>> r(residual);
    r.template head<3>() = T(inverse_sigma_xyz) * (t_bc - t_ab);
    r.template tail<3>() = T(2.0 * inverse_sigma_angle) * (q_ab.conjugate() * q_bc).vec();
    return true;
  }
};

// Solver accuracy: far below any sensor noise, so noise-free data is solved to rounding; a
// noisy problem stops once an iteration lowers the cost by less than kFunctionTolerance [C].
constexpr double kTolerance = 1e-14;
constexpr double kFunctionTolerance = 1e-10;

std::vector<PoseBlock> pose_blocks(const std::vector<Rigid3>& poses) {
  std::vector<PoseBlock> blocks(poses.size());
  for (std::size_t k = 0; k < poses.size(); ++k) {
    const Eigen::Quaterniond q = poses[k].quaternion().normalized();
    blocks[k].q = {q.x(), q.y(), q.z(), q.w()};
    blocks[k].t = {poses[k].translation.x(), poses[k].translation.y(), poses[k].translation.z()};
  }
  return blocks;
}

ceres::CostFunction* observation_cost(const OptimumObservation& o, const ObservationNoise& noise) {
  if (noise.spherical)
    return new ceres::AutoDiffCostFunction<SphericalResidual, 3, 4, 3, 3>(
        new SphericalResidual{range_bearing_of(mrpt_from_robot(o.p_robot)), noise});
  return new ceres::AutoDiffCostFunction<CartesianResidual, 3, 4, 3, 3>(
      new CartesianResidual{o.p_robot, 1.0 / noise.std_range});
}

// The observations' loss; nullptr is least squares. Ceres's scale a is the residual norm where
// the loss bends, so loss_scale sigmas of the whitened residual. auto: robust only when the
// association is another estimator's, whose wrong matches are outliers.
ceres::LossFunction* observation_loss(const BatchOptimumOptions& options) {
  OptimumLoss loss = options.loss;
  if (loss == OptimumLoss::Auto)
    loss = options.association == OptimumAssociation::RelativePoint ? OptimumLoss::Cauchy : OptimumLoss::None;
  switch (loss) {
    case OptimumLoss::Huber: return new ceres::HuberLoss(options.loss_scale);
    case OptimumLoss::Cauchy: return new ceres::CauchyLoss(options.loss_scale);
    case OptimumLoss::None:
    case OptimumLoss::Auto: break;
  }
  return nullptr;
}

// The residual blocks of every observation (one loss shared by all), step measurement and, with
// the constant-velocity prior, every three consecutive poses without a measured step.
void add_residuals(ceres::Problem& ceres_problem, OptimumProblem& problem, std::vector<PoseBlock>& poses,
                   const ObservationNoise& noise, ceres::LossFunction* loss) {
  for (const OptimumObservation& o : problem.observations) {
    PoseBlock& pose = poses[o.pose];
    double* landmark = problem.landmarks[o.landmark].data();
    ceres_problem.AddResidualBlock(observation_cost(o, noise), loss, pose.q.data(), pose.t.data(), landmark);
  }
  for (std::size_t k = 1; k < problem.steps.size() && k < poses.size(); ++k) {
    if (!problem.steps[k]) continue;
    const StepMeasurement& m = *problem.steps[k];
    auto* cost = new ceres::AutoDiffCostFunction<OdometryResidual, 6, 4, 3, 4, 3>(
        new OdometryResidual{m.previous_T_current.quaternion().normalized(), m.previous_T_current.translation,
                             1.0 / m.std_xyz, 1.0 / m.std_angle_rad});
    ceres_problem.AddResidualBlock(cost, nullptr, poses[k - 1].q.data(), poses[k - 1].t.data(), poses[k].q.data(),
                                   poses[k].t.data());
  }
  if (!problem.constant_velocity) return;
  const ConstantVelocity& v = *problem.constant_velocity;
  for (std::size_t k = 2; k < problem.steps.size() && k < poses.size(); ++k) {
    if (problem.steps[k] || problem.steps[k - 1]) continue;  // a measured step is not smoothed
    auto* cost = new ceres::AutoDiffCostFunction<ConstantVelocityResidual, 6, 4, 3, 4, 3, 4, 3>(
        new ConstantVelocityResidual{1.0 / v.std_xyz, 1.0 / v.std_angle_rad});
    ceres_problem.AddResidualBlock(cost, nullptr, poses[k - 2].q.data(), poses[k - 2].t.data(), poses[k - 1].q.data(),
                                   poses[k - 1].t.data(), poses[k].q.data(), poses[k].t.data());
  }
}

}  // namespace

ObservationNoise observation_noise(const RangeBearingSensor& sensor) {
  ObservationNoise noise;
  noise.spherical = sensor.std_range > 0 && sensor.std_yaw_rad > 0;
  if (sensor.std_range > 0) noise.std_range = sensor.std_range;
  if (noise.spherical) {
    noise.std_yaw_rad = sensor.std_yaw_rad;
    // A planar sensor (a laser's scan plane: Victoria Park) states no pitch deviation; its points
    // lie in the plane, held there with the bearing's [C].
    noise.std_pitch_rad = sensor.std_pitch_rad > 0 ? sensor.std_pitch_rad : sensor.std_yaw_rad;
  }
  return noise;
}

OptimumReport solve_optimum(OptimumProblem& problem, const ObservationNoise& noise,
                            const BatchOptimumOptions& options) {
  relax::quiet_solver_warnings();
  OptimumReport report;
  if (problem.world_T_robot.empty()) return report;
  std::vector<PoseBlock> poses = pose_blocks(problem.world_T_robot);
  const std::unique_ptr<ceres::LossFunction> loss(observation_loss(options));
  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;  // one loss, many blocks
  ceres::Problem ceres_problem(problem_options);
  add_residuals(ceres_problem, problem, poses, noise, loss.get());
  for (std::size_t k = 0; k < poses.size(); ++k) {
    if (!ceres_problem.HasParameterBlock(poses[k].q.data())) continue;  // a frame without observations
    ceres_problem.SetManifold(poses[k].q.data(), new ceres::EigenQuaternionManifold);
  }
  // The gauge: the first pose stays where it starts, as every estimator's map frame does.
  if (ceres_problem.HasParameterBlock(poses[0].q.data())) {
    ceres_problem.SetParameterBlockConstant(poses[0].q.data());
    ceres_problem.SetParameterBlockConstant(poses[0].t.data());
  }
  if (ceres_problem.NumResidualBlocks() == 0) {
    report.usable = true;
    report.termination = "no observation with a known landmark";
    return report;
  }

  ceres::Solver::Options solver;
  // The normal equations whole, CHOLMOD's fill-reducing ordering: a landmark is seen from a
  // hundred poses and more, so eliminating the landmarks first (the Schur complement) leaves
  // the poses a dense band, slower to factor than the whole sparse system [C].
  solver.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  solver.sparse_linear_algebra_library_type = ceres::SUITE_SPARSE;
  solver.num_threads = 1;  // determinism
  solver.max_num_iterations = options.max_iterations;
  solver.function_tolerance = kFunctionTolerance;
  solver.gradient_tolerance = kTolerance;
  solver.parameter_tolerance = kTolerance;
  solver.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  const auto start = std::chrono::steady_clock::now();
  ceres::Solve(solver, &ceres_problem, &summary);
  report.solve_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report.usable = summary.IsSolutionUsable();
  report.solver_iterations = static_cast<int>(summary.iterations.size());
  report.initial_cost = summary.initial_cost;
  report.final_cost = summary.final_cost;
  report.termination = summary.message;
  for (std::size_t k = 0; k < poses.size(); ++k) {
    const Eigen::Quaterniond q(poses[k].q[3], poses[k].q[0], poses[k].q[1], poses[k].q[2]);
    problem.world_T_robot[k] = Rigid3::from(q, Eigen::Vector3d(poses[k].t[0], poses[k].t[1], poses[k].t[2]));
  }
  return report;
}

}  // namespace relslam::eval
