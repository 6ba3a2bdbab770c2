// Pose integrity and relocalisation for the adaptive preset (pose_integrity.hpp): the pose from
// the planes' lines, each plane's agreement with the map, and the whole-map match when lost.

#include "relslam/plane/pose_integrity.hpp"

#include "relslam/plane/view_evidence.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace relslam::plane {
namespace {

// Relocalisation needs this many planes in view on the map [C]: two lines fit a pose anywhere
// the map has two walls at their angle; the third is what can rule the others out.
constexpr int kRecoverySupport = 3;

// |sin| of the angle between two directions: parallel and antiparallel planes constrain alike.
double direction_gap(double angle1, double angle2) { return std::abs(std::sin(angle1 - angle2)); }

bool two_directions(std::span<const LinePair> pairs, const std::vector<char>& active, double min_angle_rad) {
  const double bound = std::sin(min_angle_rad);
  for (std::size_t i = 0; i < pairs.size(); ++i)
    for (std::size_t j = i + 1; j < pairs.size(); ++j)
      if (active[i] && active[j] && direction_gap(pairs[i].mapped.angle(), pairs[j].mapped.angle()) > bound)
        return true;
  return false;
}

// How far `pair` is from agreeing, as a share of the bounds: at most 1 agrees.
double residual(const LinePair& pair, const PlanarPose& world_T_robot, const IntegrityOptions& o) {
  const PlaneObject world = pair.seen.transformed(world_T_robot);
  const Eigen::Vector2d n = pair.mapped.normal(), u = pair.mapped.tangent();
  const double d = pair.mapped.offset();
  const double along = std::abs(wrap_angle(world.angle() - pair.mapped.angle())) / o.angle_bound_rad;
  const double across = std::max(std::abs(n.dot(world.a) + d), std::abs(n.dot(world.b) + d)) / o.offset_bound;
  // Along the line: a plane seen no longer than its map plane must lie within it (so a wall
  // piece cannot stand in for its neighbour along a corridor); a longer one, seen beyond a map
  // plane that is only a piece of its wall, must overlap it. Each widened by overlap_margin.
  const double sa = u.dot(world.a - pair.mapped.a), sb = u.dot(world.b - pair.mapped.a);
  const double lo = std::min(sa, sb), hi = std::max(sa, sb), length = pair.mapped.length();
  const double gap = (hi - lo <= length ? std::max(-lo, hi - length) : std::max(lo - length, -hi)) - o.overlap_margin;
  return std::max({along, across, gap > 0 ? 1.0 + gap : 0.0});
}

std::vector<LinePair> active_pairs(std::span<const LinePair> pairs, const std::vector<char>& active) {
  std::vector<LinePair> out;
  for (std::size_t i = 0; i < pairs.size(); ++i)
    if (active[i]) out.push_back(pairs[i]);
  return out;
}

// Whether `pose` follows from the last valid one by a robot's motion.
bool continuous(const PlanarPose& pose, const std::optional<std::pair<PlanarPose, int>>& previous,
                const IntegrityOptions& o) {
  if (!previous || previous->second > o.continuity_window) return true;
  const double gap = std::max(1, previous->second);
  return (pose.translation - previous->first.translation).norm() <= o.max_step * gap + o.offset_bound &&
         std::abs(wrap_angle(pose.heading - previous->first.heading)) <= o.max_turn_rad * gap + o.angle_bound_rad;
}

// The planes in view that `pose` puts on the map, each with the map plane it agrees with best
// (a registered one with its own, `known`): false when a registered plane does not agree there,
// as Rule 1's tracking of it is better evidence than a fit of two lines.
bool support_at(const PlanarPose& pose, std::span<const PlaneObject> seen, std::span<const PlaneObject> map,
                std::span<const int> known, const IntegrityOptions& o, std::vector<LinePair>& support) {
  support.clear();
  for (std::size_t i = 0; i < seen.size(); ++i) {
    if (i < known.size() && known[i] >= 0) {
      const LinePair pair{seen[i], map[static_cast<std::size_t>(known[i])]};
      if (residual(pair, pose, o) > 1.0) return false;
      support.push_back(pair);
      continue;
    }
    double lowest = 1.0;
    const PlaneObject* match = nullptr;
    for (const PlaneObject& m : map)
      if (const double r = residual({seen[i], m}, pose, o); r <= lowest) lowest = r, match = &m;
    if (match != nullptr) support.push_back({seen[i], *match});
  }
  return true;
}

}  // namespace

bool contradicted(const PlanarPose& pose, std::span<const PlaneObject> seen, std::span<const PlaneObject> map,
                  const IntegrityOptions& o) {
  // The pose check's bounds doubled for covering a mapped wall: the place is fitted to the
  // planes in view within them.
  const CoverBounds cover{2 * o.offset_bound, 2 * o.angle_bound_rad};
  return view_conflict(pose, seen, map, o.field_of_view, o.view_evidence, cover) != ViewConflict::None;
}

std::string_view to_string(PoseReason reason) {
  switch (reason) {
    case PoseReason::Lines: return "lines";
    case PoseReason::MotionModel: return "motion_model";
    case PoseReason::Recovered: return "recovered";
    case PoseReason::Ends: return "ends";
    case PoseReason::NoPlanes: return "no_planes";
    case PoseReason::OneDirection: return "one_direction";
    case PoseReason::Disagree: return "disagree";
    case PoseReason::Jump: return "jump";
  }
  return "?";
}

bool within_reach(const PlanarPose& pose, const PlanarPose& previous, int iterations, const IntegrityOptions& options) {
  return continuous(pose, std::pair(previous, iterations), options);
}

std::optional<PlanarPose> fit_pose_to_lines(std::span<const LinePair> pairs, double min_angle_rad) {
  if (!two_directions(pairs, std::vector<char>(pairs.size(), 1), min_angle_rad)) return std::nullopt;
  double c = 0, s = 0;
  for (const LinePair& p : pairs) {
    const double delta = p.mapped.angle() - p.seen.angle();
    c += std::cos(delta);
    s += std::sin(delta);
  }
  const double heading = std::atan2(s, c);
  const Eigen::Matrix2d rotation = planar_rotation(heading);
  Eigen::Matrix2d a = Eigen::Matrix2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  for (const LinePair& p : pairs) {
    // n·(R m_seen + t) + d = 0 on the map plane's line.
    const Eigen::Vector2d n = p.mapped.normal();
    a += n * n.transpose();
    b += n * (-p.mapped.offset() - n.dot(rotation * p.seen.midpoint()));
  }
  return PlanarPose{a.ldlt().solve(b), wrap_angle(heading)};
}

bool agrees(const LinePair& pair, const PlanarPose& world_T_robot, const IntegrityOptions& options) {
  return residual(pair, world_T_robot, options) <= 1.0;
}

IntegrityResult check_pose(std::span<const LinePair> pairs, const IntegrityOptions& options,
                           const std::optional<std::pair<PlanarPose, int>>& previous) {
  IntegrityResult out;
  if (pairs.empty()) return out;
  std::vector<char> active(pairs.size(), 1);
  out.reason = PoseReason::OneDirection;
  out.planes = static_cast<int>(pairs.size());
  if (!two_directions(pairs, active, options.min_angle_rad)) return out;
  int dropped = 0;
  while (true) {
    const std::vector<LinePair> used = active_pairs(pairs, active);
    const PlanarPose pose = *fit_pose_to_lines(used, options.min_angle_rad);
    std::size_t worst = pairs.size();
    double worst_residual = 1.0;
    for (std::size_t i = 0; i < pairs.size(); ++i)
      if (active[i] && residual(pairs[i], pose, options) > worst_residual)
        worst_residual = residual(pairs[i], pose, options), worst = i;
    if (worst == pairs.size()) {
      out.world_T_robot = pose;
      out.planes = static_cast<int>(used.size());
      out.valid = continuous(pose, previous, options);
      out.reason = out.valid ? PoseReason::Lines : PoseReason::Jump;
      return out;
    }
    // A pair that does not agree is dropped only while the rest outnumber the dropped ones.
    active[worst] = 0;
    ++dropped;
    if (static_cast<int>(used.size()) - 1 <= dropped || !two_directions(pairs, active, options.min_angle_rad)) {
      out.reason = PoseReason::Disagree;
      return out;
    }
  }
}

std::optional<IntegrityResult> relocalize(std::span<const PlaneObject> seen, std::span<const PlaneObject> map,
                                          const std::optional<NearPose>& near, const IntegrityOptions& options,
                                          std::span<const int> known) {
  const double bound = std::sin(options.min_angle_rad);
  const auto known_at = [&](std::size_t i) { return i < known.size() ? known[i] : -1; };
  std::vector<IntegrityResult> found;  // distinct poses (further apart than offset_bound)
  std::vector<LinePair> support;
  for (std::size_t i = 0; i < seen.size(); ++i)
    for (std::size_t j = 0; j < seen.size(); ++j) {
      if (i == j || direction_gap(seen[i].angle(), seen[j].angle()) <= bound) continue;
      const double turn = wrap_angle(seen[j].angle() - seen[i].angle());
      for (std::size_t p = 0; p < map.size(); ++p)
        for (std::size_t q = 0; q < map.size(); ++q) {
          if (p == q || std::abs(wrap_angle(map[q].angle() - map[p].angle() - turn)) > 2 * options.angle_bound_rad)
            continue;
          // A plane in view registered to a map plane (Rule 1) is tried with that one only.
          if ((known_at(i) >= 0 && known_at(i) != static_cast<int>(p)) ||
              (known_at(j) >= 0 && known_at(j) != static_cast<int>(q)))
            continue;
          const LinePair two[2] = {{seen[i], map[p]}, {seen[j], map[q]}};
          const std::optional<PlanarPose> pose = fit_pose_to_lines(two, options.min_angle_rad);
          if (!pose || !agrees(two[0], *pose, options) || !agrees(two[1], *pose, options)) continue;
          if (near && (pose->translation - near->pose.translation).norm() > near->radius) continue;
          if (!support_at(*pose, seen, map, known, options, support)) continue;
          const IntegrityResult checked = check_pose(support, options);
          if (!checked.valid || contradicted(checked.world_T_robot, seen, map, options)) continue;
          const auto same = std::ranges::find_if(found, [&](const IntegrityResult& f) {
            return (f.world_T_robot.translation - checked.world_T_robot.translation).norm() <= options.offset_bound;
          });
          if (same == found.end()) found.push_back(checked);
          else if (checked.planes > same->planes) *same = checked;
        }
    }
  // The best must have kRecoverySupport planes and every other place at least two fewer.
  const auto best = std::ranges::max_element(found, {}, &IntegrityResult::planes);
  if (best == found.end() || best->planes < kRecoverySupport) return std::nullopt;
  for (auto f = found.begin(); f != found.end(); ++f)
    if (f != best && f->planes >= best->planes - 1) return std::nullopt;
  IntegrityResult out = *best;
  out.reason = PoseReason::Recovered;
  return out;
}

}  // namespace relslam::plane
