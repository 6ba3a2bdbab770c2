#pragma once
// Planar-world map files (scenarios/maps/*.json): the walls, the robot's path and the sensor the
// map was made for, read into sim::PlanarMap (relative_plane_em.md §3.7; the format is in
// sim/README.md). Maps are data, so JSON stays out of sim/.

#include "relslam/sim/planar_map.hpp"

#include <filesystem>
#include <string>

namespace relslam::eval {

// Reads and checks a map file. Throws InputError naming the file, the line, the field
// ("walls[3].b", "path.steps[2]") and the problem: malformed JSON, unknown or missing keys,
// bad values, zero-length or non-finite walls, a wall without its facing side, an empty path,
// and a path along which the map's own sensor never sees two walls at once.
sim::PlanarMap read_planar_map(const std::filesystem::path& file);
// The same from JSON text; `file` names it in messages.
sim::PlanarMap parse_planar_map(const std::string& text, const std::string& file);

}  // namespace relslam::eval
