#include "relslam/sim/planar_path.hpp"
#include "relslam/core/option_fields.hpp"

#include "checked.hpp"

#include <cmath>
#include <string>

namespace relslam::sim {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
// A length that is a whole number of steps up to rounding (4 / 0.05 = 80.00000000000001)
// must not get an extra sliver of a step.
constexpr double kWholeStepTolerance = 1e-9;

// The operation's length counted in full-speed steps: the slower of moving and turning sets
// the pace, so an ARC never exceeds either speed.
double step_span(const PathOperation& op, double speed, double turn_rate_rad) {
  return std::max(op.distance / speed, std::abs(op.angle_rad) / turn_rate_rad);
}

long long step_count(const PathOperation& op, double speed, double turn_rate_rad) {
  return std::max(1LL, static_cast<long long>(std::ceil(step_span(op, speed, turn_rate_rad) - kWholeStepTolerance)));
}

// The motion after fraction s of the operation, in the frame of its start pose.
PlanarPose partial_motion(const PathOperation& op, double s) {
  const double turned = s * op.angle_rad;
  if (op.distance == 0.0) return {Eigen::Vector2d::Zero(), turned};
  if (op.angle_rad == 0.0) return {Eigen::Vector2d(s * op.distance, 0.0), 0.0};
  // On a circle of radius r = distance / angle: (r sin φ, r (1 − cos φ)), the latter as
  // 2 r sin²(φ/2) so short arcs keep their precision.
  const double radius = op.distance / op.angle_rad;
  const double half_sine = std::sin(0.5 * turned);
  return {Eigen::Vector2d(radius * std::sin(turned), 2.0 * radius * half_sine * half_sine), turned};
}

void check_operation(std::vector<OptionIssue>& issues, const std::string& field, const PathOperation& op) {
  const bool moves = op.kind != PathOperationKind::Turn;
  if (moves) above(0.0)(issues, field + ".distance", op.distance);
  if (!moves && (!std::isfinite(op.angle_rad) || op.angle_rad == 0.0))
    issues.push_back(
        {field + ".angle_deg", "must be a finite non-zero angle, got " + format_number(op.angle_rad / kDegree)});
  if (op.kind == PathOperationKind::Arc && !std::isfinite(op.angle_rad))
    issues.push_back({field + ".angle_deg", "must be finite, got " + format_number(op.angle_rad / kDegree)});
  if (op.kind == PathOperationKind::Move && op.angle_rad != 0.0)
    issues.push_back({field + ".angle_deg", "a MOVE goes straight; use ARC to turn while moving"});
  if (op.kind == PathOperationKind::Turn && op.distance != 0.0)
    issues.push_back({field + ".distance", "a TURN is in place; use ARC to move while turning"});
}

// In doubles, so that a typo (MOVE 1e300, loops 2e9) cannot overflow before check() rejects it.
double iteration_total(const PathProgram& p) {
  double per_loop = 0, then = 0;
  for (const PathOperation& op : p.steps)
    per_loop += std::ceil(step_span(op, p.speed, p.turn_rate_rad) - kWholeStepTolerance);
  for (const PathOperation& op : p.then)
    then += std::ceil(step_span(op, p.speed, p.turn_rate_rad) - kWholeStepTolerance);
  return 1.0 + p.loops * per_loop + then;
}

}  // namespace

long long iteration_count(const PathProgram& p) {
  long long per_loop = 0, then = 0;
  for (const PathOperation& op : p.steps) per_loop += step_count(op, p.speed, p.turn_rate_rad);
  for (const PathOperation& op : p.then) then += step_count(op, p.speed, p.turn_rate_rad);
  return 1 + static_cast<long long>(p.loops) * per_loop + then;
}

std::vector<OptionIssue> check(const PathProgram& p) {
  std::vector<OptionIssue> issues;
  if (!p.start.translation.allFinite() || !std::isfinite(p.start.heading))
    issues.push_back({"start", "must be finite, got (" + format_number(p.start.translation.x()) + ", " +
                                   format_number(p.start.translation.y()) + ", " +
                                   format_number(p.start.heading / kDegree) + "°)"});
  above(0.0)(issues, "speed", p.speed);
  above(0.0)(issues, "turn_rate_deg", p.turn_rate_rad / kDegree);
  at_least(1)(issues, "loops", p.loops);
  if (p.steps.empty()) issues.push_back({"steps", "is empty; a path needs at least one MOVE, TURN or ARC"});
  for (std::size_t i = 0; i < p.steps.size(); ++i)
    check_operation(issues, "steps[" + std::to_string(i) + "]", p.steps[i]);
  for (std::size_t i = 0; i < p.then.size(); ++i) check_operation(issues, "then[" + std::to_string(i) + "]", p.then[i]);
  if (issues.empty() && iteration_total(p) > static_cast<double>(kMaxPathIterations))
    issues.push_back({"steps", "the path takes " + format_number(iteration_total(p)) + " iterations; the limit is " +
                                   std::to_string(kMaxPathIterations)});
  return issues;
}

PlanarPath::PlanarPath(const PathProgram& program) {
  const PathProgram& p = checked(program);
  poses_.reserve(static_cast<std::size_t>(iteration_count(p)));
  poses_.push_back(p.start);
  auto run = [&](const PathOperation& op) {
    const PlanarPose from = poses_.back();
    const double span = step_span(op, p.speed, p.turn_rate_rad);
    const long long n = step_count(op, p.speed, p.turn_rate_rad);
    // Full-speed steps, then the last one lands on the target exactly (fraction 1).
    for (long long i = 1; i <= n; ++i) poses_.push_back(from * partial_motion(op, i == n ? 1.0 : i / span));
    operation_ends_.push_back(iterations() - 1);
  };
  for (int loop = 0; loop < p.loops; ++loop)
    for (const PathOperation& op : p.steps) run(op);
  for (const PathOperation& op : p.then) run(op);
}

}  // namespace relslam::sim
