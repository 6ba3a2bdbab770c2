#pragma once
// The Ceres Solver side of the global relaxation (beyond the thesis): solves a
// point::RelaxationProblem. The only code of libslam that includes Ceres; libslam's algorithm
// reaches it through point::GroupRelaxer (the harness's batch optimum is the other user).

#include "relslam/point/group_relaxation.hpp"

namespace relslam::relax {

// Every group-to-world transform at once: each tie a 3-vector residual (the two groups' world
// positions of one point) under a Cauchy loss of problem.loss_scale; rotations on Ceres's
// quaternion manifold, translations free, fixed groups constant; sparse normal Cholesky, one
// thread (the same input gives the same bits). Leaves the problem as given when nothing is free
// or no tie touches a free group.
point::RelaxationReport solve_relaxation(point::RelaxationProblem& problem);

// Ceres reports through glog, which nothing here initialises: only glog's errors reach stderr
// after this (once per process; every Ceres user calls it before solving).
void quiet_solver_warnings();

}  // namespace relslam::relax
