#include "relslam/sim/map_generator.hpp"

#include "map_layout.hpp"
#include "relslam/sim/planar_sight.hpp"
#include "relslam/sim/viewing_frustum.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <string>

namespace relslam::sim {

using layout::Layout;
using layout::Vec;

std::span<const MapFamily> generated_families() { return std::span<const MapFamily>(kMapFamilies).subspan(1); }

std::string_view to_string(MapFamily family) {
  switch (family) {
    case MapFamily::None: return "none";
    case MapFamily::ConvexRoom: return "convex_room";
    case MapFamily::InnerWalls: return "inner_walls";
    case MapFamily::Corridor: return "corridor";
    case MapFamily::MirroredCorridor: return "mirrored_corridor";
    case MapFamily::Office: return "office";
    case MapFamily::Clutter: return "clutter";
  }
  return "none";
}

std::vector<OptionIssue> check(const MapGeneratorOptions& options) {
  std::vector<OptionIssue> issues;
  if (options.family == MapFamily::None) issues.push_back({"family", "names no family to generate"});
  // The corridors are at least 2.5 wide: more than 1.2 would leave the robot no room.
  if (!(options.clearance >= 0.2 && options.clearance <= 1.2))
    issues.push_back({"clearance", "must be in [0.2, 1.2], got " + format_number(options.clearance)});
  return issues;
}

namespace {

// The heading change from direction u to v in (-π, π]; a reversal is +π exactly.
double turn_between(const Vec& u, const Vec& v) {
  const double turn = std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
  return std::abs(turn) > std::numbers::pi - 1e-9 ? std::numbers::pi : turn;
}

// MOVE along each leg from waypoints[first], turning in place between legs; `legs` legs at most.
void add_legs(std::vector<PathOperation>& ops, const std::vector<Vec>& waypoints, std::size_t legs) {
  for (std::size_t i = 0; i < legs && i + 1 < waypoints.size(); ++i) {
    const Vec leg = waypoints[i + 1] - waypoints[i];
    if (i > 0) ops.push_back(PathOperation::turn(turn_between(waypoints[i] - waypoints[i - 1], leg)));
    ops.push_back(PathOperation::move(leg.norm()));
  }
}

// The path through the layout's waypoints; a path that ends where it began turns back to its
// first heading, so that the next loop (or the closing legs) starts as the first did.
PathProgram path_through(const Layout& l) {
  const std::vector<Vec>& w = l.waypoints;
  PathProgram path;
  const Vec first = w[1] - w[0];
  path.start = PlanarPose::from(w[0].x(), w[0].y(), std::atan2(first.y(), first.x()));
  path.loops = l.loops;
  add_legs(path.steps, w, w.size() - 1);
  const bool closed = (w.back() - w.front()).norm() < 1e-9;
  if (closed) path.steps.push_back(PathOperation::turn(turn_between(w[w.size() - 1] - w[w.size() - 2], first)));
  if (closed && l.closing_legs > 0) add_legs(path.then, w, static_cast<std::size_t>(l.closing_legs));
  return path;
}

Layout draw_layout(MapFamily family, RandomSequence& rng, double clearance) {
  switch (family) {
    case MapFamily::ConvexRoom: return layout::convex_room(rng);
    case MapFamily::InnerWalls: return layout::inner_walls_room(rng, clearance);
    case MapFamily::Corridor: return layout::corridor(rng, clearance, false);
    case MapFamily::MirroredCorridor: return layout::corridor(rng, clearance, true);
    case MapFamily::Office: return layout::office(rng);
    case MapFamily::Clutter: return layout::clutter_room(rng, clearance);
    case MapFamily::None: break;
  }
  return {};
}

// The layout turned by `angle` about the origin: arbitrary orientation for every family.
void rotate(Layout& l, double angle) {
  const Eigen::Rotation2Dd r(angle);
  for (Wall& w : l.walls) {
    w.a = r * w.a;
    w.b = r * w.b;
  }
  for (Vec& p : l.waypoints) p = r * p;
}

PlanarMap map_of(const Layout& l, const MapGeneratorOptions& options) {
  PlanarMap map;
  map.name = "generated " + std::string(to_string(options.family)) + " " + std::to_string(options.seed);
  map.description = l.description;
  // Pieces cut short at corners and gaps are dropped; ids stay positions in the map.
  for (const Wall& w : l.walls)
    if (w.length() >= kMinGeneratedWall) {
      map.world.walls.push_back(w);
      map.world.walls.back().id = static_cast<int>(map.world.walls.size()) - 1;
    }
  map.path = path_through(l);
  map.sensor.mode = PlaneVisibility::Frustum;
  map.sensor.frustum = ViewingFrustum::small();
  map.sensor.noise = PlaneNoiseOptions::none();
  return map;
}

// The least distance from any pose of the path to any wall.
double least_clearance(const PlanarMap& map, const PlanarPath& path) {
  double least = std::numeric_limits<double>::infinity();
  for (int k = 0; k < path.iterations(); ++k)
    for (const Wall& w : map.world.walls)
      least = std::min(least, layout::distance_to_segment(path.world_T_robot(k).translation, w.a, w.b));
  return least;
}

}  // namespace

std::optional<std::string> generated_map_problem(const PlanarMap& map, double clearance) {
  for (const Wall& w : map.world.walls)
    if (!(w.length() >= kMinGeneratedWall)) return "wall " + std::to_string(w.id) + " is shorter than the least";
  if (const auto issues = check(map.world); !issues.empty()) return issues.front().field + ": " + issues.front().problem;
  if (const auto issues = check(map.path); !issues.empty()) return issues.front().field + ": " + issues.front().problem;
  try {
    const PlanarPath path(map.path);
    if (const auto crossing = first_wall_crossing(map, path))
      return "the path crosses wall " + std::to_string(crossing->wall);
    if (first_exit_from_map(map, path)) return "the path leaves the map";
    const double least = least_clearance(map, path);
    if (least < clearance - 1e-9) return "the path comes within " + format_number(least) + " of a wall";
    for (const char* preset : {"small", "large"}) {
      PlanarMap seen = map;
      seen.sensor.frustum = *frustum_preset(preset);
      if (!first_iteration_seeing(seen, path, 2)) return std::string("never two walls in the ") + preset + " frustum";
    }
  } catch (const OptionError& e) {
    return e.field() + ": " + e.problem();
  }
  return std::nullopt;
}

PlanarMap generate_map(const MapGeneratorOptions& options) {
  if (const auto issues = check(options); !issues.empty()) throw OptionError(issues.front().field, issues.front().problem);
  // A drawn layout that fails the checks is drawn again from the next key: the result is still
  // a function of the options alone.
  constexpr int kAttempts = 200;
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    RandomSequence rng(options.seed, Stream::MapLayout, static_cast<std::uint64_t>(options.family),
                       static_cast<std::uint64_t>(attempt));
    Layout l = draw_layout(options.family, rng, options.clearance);
    if (l.walls.size() < 2 || l.waypoints.size() < 2) continue;
    rotate(l, rng.uniform(0.0, 2.0 * std::numbers::pi));
    PlanarMap map = map_of(l, options);
    if (!generated_map_problem(map, options.clearance)) return map;
  }
  throw OptionError("seed", "no valid " + std::string(to_string(options.family)) + " map in " +
                                std::to_string(kAttempts) + " draws");
}

}  // namespace relslam::sim
