#include "relslam/relax/ceres_relaxation.hpp"

#include <ceres/ceres.h>
#include <ceres/rotation.h>
#include <glog/logging.h>

#include <array>
#include <memory>
#include <vector>

namespace relslam::relax {
namespace {

// world_T_a * p_a - world_T_b * p_b with each transform a quaternion (x, y, z, w: Eigen's
// storage order, matching EigenQuaternionManifold) and a translation.
struct TieResidual {
  Eigen::Vector3d p_a, p_b;
  double weight;

  template <typename T>
  bool operator()(const T* q_a, const T* t_a, const T* q_b, const T* t_b, T* residual) const {
    const Eigen::Map<const Eigen::Quaternion<T>> rotation_a(q_a), rotation_b(q_b);
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> translation_a(t_a), translation_b(t_b);
    Eigen::Map<Eigen::Matrix<T, 3, 1>> r(residual);
    r = T(weight) * ((rotation_a * p_a.cast<T>() + translation_a) - (rotation_b * p_b.cast<T>() + translation_b));
    return true;
  }
};

// Solver accuracy: far below any sensor noise, so a consistent problem is solved to rounding.
constexpr double kTolerance = 1e-14;
// A noisy problem stops once an iteration lowers the cost by less than this share: the last
// iterations to 1e-14 moved no landmark measurably and took most of the time (S-40 cut to five
// loops: final mean landmark error 0.064 at 1e-14, 0.063 here; solves 41.5 s in all, longest
// 2.8 s, against 16.4 s and 0.79 s). A consistent problem's cost falls by orders of magnitude
// per iteration, so it still ends on the gradient and parameter tolerances.
constexpr double kFunctionTolerance = 1e-6;
constexpr int kMaxIterations = 100;

}  // namespace

// Ceres reports through glog, which nothing here initialises: a Levenberg-Marquardt step whose
// linear solve fails (CHOLMOD: not positive definite; met on Victoria Park's whole log with the
// adaptive preset) printed "WARNING: Logging before InitGoogleLogging()" and the message in the
// middle of a run, though the solver just retries with more damping. The outcome is in the report
// (solved, iterations); only glog's errors still reach stderr.
void quiet_solver_warnings() {
  static const bool once = [] {
    FLAGS_minloglevel = google::GLOG_ERROR;
    return true;
  }();
  (void)once;
}

point::RelaxationReport solve_relaxation(point::RelaxationProblem& problem) {
  quiet_solver_warnings();
  point::RelaxationReport report;
  const std::size_t n = problem.world_T_group.size();
  std::vector<std::array<double, 4>> quaternions(n);
  std::vector<std::array<double, 3>> translations(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Quaterniond q = problem.world_T_group[i].quaternion().normalized();
    quaternions[i] = {q.x(), q.y(), q.z(), q.w()};
    translations[i] = {problem.world_T_group[i].translation.x(), problem.world_T_group[i].translation.y(),
                       problem.world_T_group[i].translation.z()};
  }

  // One loss per tie: the weighted residual's scale is the loss scale weighted alike, so the
  // scale stays a distance in map units whatever the weight.
  std::vector<std::unique_ptr<ceres::LossFunction>> losses;
  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem ceres_problem(problem_options);
  std::vector<bool> used(n, false);
  bool any_free = false;
  for (const point::GroupTie& tie : problem.ties) {
    if (problem.fixed[tie.a] && problem.fixed[tie.b]) continue;
    auto* cost =
        new ceres::AutoDiffCostFunction<TieResidual, 3, 4, 3, 4, 3>(new TieResidual{tie.p_a, tie.p_b, tie.weight});
    losses.push_back(std::make_unique<ceres::CauchyLoss>(problem.loss_scale * tie.weight));
    ceres_problem.AddResidualBlock(cost, losses.back().get(), quaternions[tie.a].data(), translations[tie.a].data(),
                                   quaternions[tie.b].data(), translations[tie.b].data());
    used[tie.a] = used[tie.b] = true;
    any_free = true;
  }
  if (!any_free) return report;
  for (std::size_t i = 0; i < n; ++i) {
    if (!used[i]) continue;
    ceres_problem.SetManifold(quaternions[i].data(), new ceres::EigenQuaternionManifold);
    if (problem.fixed[i]) {
      ceres_problem.SetParameterBlockConstant(quaternions[i].data());
      ceres_problem.SetParameterBlockConstant(translations[i].data());
    }
  }

  ceres::Solver::Options options;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  // Eigen's sparse LDLT rather than SuiteSparse's CHOLMOD: the same solution (S-40 cut to five
  // loops: final mean landmark error equal to 15 digits) in two thirds of the time (36 solves,
  // 3.9 s against 5.9 s, twice each; bench/relax_bench.cpp's chains are too thin to tell).
  options.sparse_linear_algebra_library_type = ceres::EIGEN_SPARSE;
  options.num_threads = 1;  // determinism
  options.max_num_iterations = kMaxIterations;
  options.function_tolerance = kFunctionTolerance;
  options.gradient_tolerance = kTolerance;
  options.parameter_tolerance = kTolerance;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &ceres_problem, &summary);

  report.solved = summary.IsSolutionUsable();
  report.solver_iterations = static_cast<int>(summary.iterations.size());
  report.initial_cost = summary.initial_cost;
  report.final_cost = summary.final_cost;
  if (!report.solved) return report;
  for (std::size_t i = 0; i < n; ++i) {
    if (!used[i] || problem.fixed[i]) continue;
    const Eigen::Quaterniond q(quaternions[i][3], quaternions[i][0], quaternions[i][1], quaternions[i][2]);
    problem.world_T_group[i] = Rigid3::from(q, Eigen::Vector3d(translations[i][0], translations[i][1], translations[i][2]));
  }
  return report;
}

}  // namespace relslam::relax
