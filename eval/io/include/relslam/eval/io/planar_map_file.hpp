#pragma once
// Planar-world map files (scenarios/maps/*.json): the walls, the robot's path and the sensor the
// map was made for, read into sim::PlanarMap (the format is in
// sim/README.md). Maps are data, so JSON stays out of sim/.

#include "relslam/sim/planar_map.hpp"

#include <cstddef>
#include <filesystem>
#include <string>

namespace relslam::eval {

// The most walls a map may have. Memory grows by about 2 KB a wall while the file is read (a
// map of a million walls took 1.8 GB), and every wall is tested against every operation of the
// path; the shipped maps have at most 16. Map files are JSON, at most kMaxJsonBytes long.
inline constexpr std::size_t kMaxPlanarWalls = 10'000;

// Reads and checks a map file. Throws InputError naming the file, the line, the field
// ("walls[3].b", "path.steps[2]") and the problem: malformed JSON, unknown or missing keys,
// bad values, zero-length or non-finite walls, a wall without its facing side, more than
// kMaxPlanarWalls walls, an empty path, a path that runs through a wall (naming the step, its
// loop and the wall), and a path along which the map's own sensor never sees two walls at once
// (or one so long that finding out would take more than sim::kMaxSightWork wall tests).
sim::PlanarMap read_planar_map(const std::filesystem::path& file);
// The same from JSON text; `file` names it in messages.
sim::PlanarMap parse_planar_map(const std::string& text, const std::string& file);

// The map as map-file text, one wall a line as in scenarios/maps/: each wall's facing as its
// front normal [x, z], the path's steps in degrees, the sensor's mode, frustum preset (when it is
// one) and noise model. Read back it gives the same walls bit for bit and the same path up to the
// rounding of degrees to radians (a generated map written by relslam simulate, reused with
// planar.map).
std::string planar_map_text(const sim::PlanarMap& map);

}  // namespace relslam::eval
