#pragma once
// Internal to the algorithms layer: E02's diagnostic of Rule 13 (thesis 4.3.4, Fig 68; paper
// Fig 4): the four cross-pair offset series of one
// pair of RltPlanes, one growing and one shrinking, over the growth-phase piece ComparePlanes
// would use (Rule 18), and the four spreads with the key points Rules 13–15 choose.

#include "relslam/plane/options.hpp"
#include "relslam/plane/rlt_plane.hpp"

#include <filesystem>
#include <vector>

namespace relslam::eval {

// Writes dir/pairs.csv (per iteration of the piece: both observations' ends in the robot frame,
// so plane_observations.csv's truth can be joined on them, and the four offsets off<ab>_x,
// off<ab>_z) and dir/pair_sigma.csv (one row per key-point pair: mean, σ, the chosen one and
// the key points). The pair: of all RltPlanes whose chosen piece holds at least 20 iterations in
// which one plane clearly grows while the other shrinks, and Rule 15 finds no tie, the one whose
// lowest σ stands out most (the second lowest over the lowest). Writes both files with their
// headers only when no pair qualifies (a straight hallway has none: both cut ends move with the
// robot, so the pair of cut ends ties with the pair of real ends, Rule 15).
void write_key_point_pair_diagnostic(const std::filesystem::path& dir, const std::vector<plane::RltPlane>& planes,
                                     const plane::RelativePlaneOptions& options);

}  // namespace relslam::eval
