#pragma once
// Seeded planar maps beyond the thesis's Maps A-E: walls, a path with clearance from every wall
// and the sensor, from a family and a seed. The thesis tuned its rules on its own maps (4.3, Maps
// A-E); these families hold Relative Plane to rooms at arbitrary angles, dead ends, mirrored
// corridor pieces and clutter. Part of relslam/sim: Eigen only; the map file is written in
// eval/io (planar_map_file.hpp).

#include "relslam/core/option_issue.hpp"
#include "relslam/sim/planar_map.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace relslam::sim {

// None: no generated map (the scenario reads its map file). Every other family is described in
// docs/generated-maps.md.
enum class MapFamily {
  None,
  ConvexRoom,        // 4-8 walls at arbitrary angles around a loop
  InnerWalls,        // a convex room of 5-8 walls with an inner two-sided wall and 1-2 pillars
  Corridor,          // an L, T or U corridor with dead ends, walked out and back (180° turns)
  MirroredCorridor,  // the same, its two sides' pieces mirroring each other (thesis Rule 15 ties)
  Office,            // Map D's office loop at a random size and rotation
  Clutter,           // a convex room with short two-sided clutter walls between path and walls
};
inline constexpr MapFamily kMapFamilies[] = {MapFamily::None,   MapFamily::ConvexRoom,       MapFamily::InnerWalls,
                                             MapFamily::Corridor, MapFamily::MirroredCorridor, MapFamily::Office,
                                             MapFamily::Clutter};
// The generating families (all but None).
std::span<const MapFamily> generated_families();
std::string_view to_string(MapFamily family);  // "convex_room", "inner_walls", ...

struct MapGeneratorOptions {
  MapFamily family = MapFamily::None;
  std::uint64_t seed = 1;  // the map's own seed (the scenario's seed drives the sensor noise)
  // The least distance from every pose of the path to every wall, units [C 0.75: a quarter of
  // Map D's corridor width 3, so the robot is never closer to a wall than the thesis's robot].
  double clearance = 0.75;
};

// Every violated constraint; fields "family", "clearance".
std::vector<OptionIssue> check(const MapGeneratorOptions& options);

// The same options always give the same map, bit for bit. The map's sensor is the small frustum
// without noise; the walls face the path. Throws OptionError when the options fail check().
PlanarMap generate_map(const MapGeneratorOptions& options);

// What makes a generated map usable, the first rule broken if any: walls of at least
// kMinGeneratedWall, a path that crosses no wall, stays within the map, keeps `clearance` from
// every wall at every pose, and sees two walls at once with each frustum preset.
inline constexpr double kMinGeneratedWall = 0.4;
std::optional<std::string> generated_map_problem(const PlanarMap& map, double clearance);

}  // namespace relslam::sim
