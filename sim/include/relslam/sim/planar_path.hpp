#pragma once
// The robot's path in the planar world: a program of MOVE / TURN / ARC operations run at
// constant speeds, and the true pose it gives at every iteration (thesis 4.4.2.3 `RobotObject`
// "moves the robot along a predesignated path"; thesis 4.4.2). Part of
// relslam/sim: Eigen only.

#include "relslam/core/option_issue.hpp"
#include "relslam/core/planar_pose.hpp"

#include <numbers>
#include <vector>

namespace relslam::sim {

enum class PathOperationKind {
  Move,  // straight ahead by `distance`
  Turn,  // in place by `angle_rad` (sign = direction, + turns from +x towards +z)
  Arc,   // both at once, on a circle: `distance` along it while the heading changes by `angle_rad`
};

// Only forward motion and yaw: the motion model assumes no sideways motion [T Rule 24].
struct PathOperation {
  PathOperationKind kind = PathOperationKind::Move;
  double distance = 0.0;   // units along the path (Move, Arc)
  double angle_rad = 0.0;  // heading change (Turn, Arc)

  static PathOperation move(double distance) { return {PathOperationKind::Move, distance, 0.0}; }
  static PathOperation turn(double angle_rad) { return {PathOperationKind::Turn, 0.0, angle_rad}; }
  static PathOperation arc(double distance, double angle_rad) { return {PathOperationKind::Arc, distance, angle_rad}; }
};

struct PathProgram {
  PlanarPose start;  // world_T_robot at iteration 0; the algorithm is given it (Rule 4)
  // Distance per iteration: 1.5 units/s at the thesis's 30 it/s [R].
  double speed = 0.05;
  // Heading change per iteration while turning [R].
  double turn_rate_rad = 1.5 * std::numbers::pi / 180.0;
  int loops = 1;  // `steps` run this many times, each loop starting where the last one ended
  std::vector<PathOperation> steps;
  // Run once after the loops: Map D's partial second loop, which closes the loop [R].
  std::vector<PathOperation> then;
};

// A typo in a map must not allocate the machine away; Map D's two loops take ~3,500.
inline constexpr long long kMaxPathIterations = 10'000'000;

// Every violated constraint; fields are "speed", "turn_rate_deg", "loops", "steps[2]", ...
std::vector<OptionIssue> check(const PathProgram& program);
// Iterations a program that passes check() runs, the start pose included: 1 + every
// operation's step count.
long long iteration_count(const PathProgram& program);

// Invariants: world_T_robot(0) is the start pose; every operation ends exactly on its target
// (its last step is shortened, thesis 4.4.2), computed from the operation's start rather than by
// adding up steps, so no rounding accumulates within an operation; a TURN keeps the translation
// bit for bit.
class PlanarPath {
 public:
  // Throws OptionError when the program fails check().
  explicit PlanarPath(const PathProgram& program);

  int iterations() const { return static_cast<int>(poses_.size()); }
  const PlanarPose& world_T_robot(int k) const { return poses_.at(static_cast<std::size_t>(k)); }
  // The iteration at which each operation ends, in the order run (loops unrolled, then `then`).
  const std::vector<int>& operation_ends() const { return operation_ends_; }

 private:
  std::vector<PlanarPose> poses_;
  std::vector<int> operation_ends_;
};

}  // namespace relslam::sim
