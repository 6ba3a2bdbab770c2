#pragma once
// Global relaxation of the Relative Point map (beyond the thesis): the problem of
// solving every group-to-world transform at once, built from and written back to an RltMap.
// Eigen only: the solver itself (Ceres) lives in relslam/relax/ and is reached through
// GroupRelaxer, so libslam never sees its headers.

#include "relslam/core/rigid.hpp"
#include "relslam/point/rlt_point.hpp"

#include <functional>
#include <vector>

namespace relslam::point {

struct RltMap;

// One point known to two groups: world_T_group[a] * p_a and world_T_group[b] * p_b should be
// the same world position. Indices are into RelaxationProblem::world_T_group.
struct GroupTie {
  int a = 0;
  Eigen::Vector3d p_a = Eigen::Vector3d::Zero();  // in group a's basis frame
  int b = 0;
  Eigen::Vector3d p_b = Eigen::Vector3d::Zero();  // in group b's basis frame
  // Inverse standard deviation of the residual in sensor sigmas: p_a and p_b are averages over
  // n_a and n_b iterations, so 1/sqrt(1/n_a + 1/n_b). A short-lived temporary group's tie
  // counts less than a final group's.
  double weight = 1;
};

// Every group a rigid body; the fixed ones (the root) hold the map frame.
struct RelaxationProblem {
  std::vector<Rigid3> world_T_group;  // the start values; a solver overwrites them
  std::vector<bool> fixed;            // one per group: held constant
  std::vector<GroupTie> ties;
  double loss_scale = 0.3;  // robust loss scale, units (PointSlamOptions::relaxation_loss_scale)
};

struct RelaxationReport {
  bool solved = false;  // false: the transforms were left as given
  int solver_iterations = 0;
  double initial_cost = 0;
  double final_cost = 0;
};

// Solves a RelaxationProblem in place (relax::solve_relaxation is the Ceres one).
using GroupRelaxer = std::function<RelaxationReport(RelaxationProblem&)>;

// The groups taking part, which map's group each entry stands for, and the problem over them.
struct MapRelaxation {
  RelaxationProblem problem;
  std::vector<GroupId> groups;  // problem index -> map group id; kNone: the first frame's body
  std::vector<PointId> tie_points;  // one per tie: the point it ties
};

// A tie's gap at the problem's transforms: how far apart the two groups put the point, units.
double tie_gap(const RelaxationProblem& problem, const GroupTie& tie);

// The points with a tie whose weighted gap (tie_gap times the tie's weight: the gap of one
// observation each, whatever the groups' averaging) is over `gap`, sorted.
std::vector<PointId> points_over(const MapRelaxation& relaxation, double gap);

// The problem for `map`: one body per alive, registrable group at its current registration,
// one tie per extra group a static point belongs to (a star around its owner), and the gauge:
// a fixed body at the identity holding the first iteration's observations (the map frame,
// thesis 6.3.3), tied to the owner of each mapped point seen then. With three or more such
// ties the root group is free too, so the map frame rests on every first observation rather
// than on the root's members alone; with fewer it stays fixed. Provisional roots stay fixed.
MapRelaxation build_relaxation(const RltMap& map, double loss_scale);

// After a solve: every point a free group owns gets world_T_group * relative (and its place in
// the global index). Fixed groups and the relative maps are untouched. Returns the points moved.
int apply_relaxation(RltMap& map, const MapRelaxation& relaxation);

}  // namespace relslam::point
