#pragma once
// The Ceres Solver side of the global relaxation (beyond the thesis, issue 19): solves a
// point::RelaxationProblem. The only code of relslam that includes Ceres; libslam's algorithm
// reaches it through point::GroupRelaxer.

#include "relslam/point/group_relaxation.hpp"

namespace relslam::relax {

// Every group-to-world transform at once: each tie a 3-vector residual (the two groups' world
// positions of one point) under a Cauchy loss of problem.loss_scale; rotations on Ceres's
// quaternion manifold, translations free, fixed groups constant; sparse normal Cholesky, one
// thread (the same input gives the same bits). Leaves the problem as given when nothing is free
// or no tie touches a free group.
point::RelaxationReport solve_relaxation(point::RelaxationProblem& problem);

}  // namespace relslam::relax
