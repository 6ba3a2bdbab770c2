#pragma once
// The pieces every generated family is built from (map_generator.hpp): walls facing a given
// side, a straight side cut into pieces with gaps, convex polygons, and the path as a list of
// waypoints driven straight between them with turns in place. Private to relslam/sim.

#include "relslam/core/option_issue.hpp"
#include "relslam/sim/planar_map.hpp"
#include "relslam/sim/random.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace relslam::sim::layout {

using Vec = Eigen::Vector2d;

// What a family draws, in its own frame; map_generator.cpp rotates it and makes the map.
struct Layout {
  std::vector<Wall> walls;
  // The path: straight from each waypoint to the next, turning in place at each. A closed loop
  // repeats its first waypoint last; an out-and-back leg lists the dead end once and comes back
  // (a 180° turn there).
  std::vector<Vec> waypoints;
  int loops = 1;
  // Run once after the loops (waypoints[0] onwards again): the partial loop that closes a loop
  // as Map D's does, at most this many legs.
  int closing_legs = 0;
  std::string description;
};

// Adds a one-sided wall a-b whose front looks towards `facing` (a direction), or a two-sided one.
void add_wall(Layout& layout, const Vec& a, const Vec& b, const Vec& facing, bool one_sided = true);

// How a straight side is cut: pieces of `piece_min`..`piece_max` with gaps of
// `gap_min`..`gap_max` between them (Map D: pieces of 4, gaps of 1). Equal bounds give a regular
// grid; a grid drawn once and used on both sides of a corridor mirrors them.
struct PieceGrid {
  double piece_min = 4.0, piece_max = 4.0;
  double gap_min = 1.0, gap_max = 1.0;
};
// Cut points along a line from `s0` to `s1` (a gap of half a gap at each end, as Map D's
// corners): pairs [from, to] of each piece.
std::vector<std::pair<double, double>> piece_positions(double s0, double s1, const PieceGrid& grid,
                                                       RandomSequence& rng);
// Adds the pieces of [s0, s1] on the line origin + s·direction that lie in [lo, hi], facing
// `facing` (the generator drops pieces shorter than kMinGeneratedWall).
void add_pieces(Layout& layout, const Vec& origin, const Vec& direction,
                const std::vector<std::pair<double, double>>& pieces, double lo, double hi, const Vec& facing);

// A convex polygon of n corners on a circle of radius r about the origin, counter-clockwise,
// the angle between neighbours in [min_gap, max_gap] radians; empty if none was found.
std::vector<Vec> convex_polygon(int n, double r, double min_gap, double max_gap, RandomSequence& rng);
// Its edges as whole walls facing inwards.
void add_polygon_walls(Layout& layout, const std::vector<Vec>& corners);
// The polygon moved inwards by `distance` from every edge, closed (first corner again at the
// end): a loop path along the walls of a convex room, as Map D's robot drives 1.5 from its
// walls, so that the small frustum sees the wall beside it and the next one ahead together.
// Empty when an edge would be shorter than `least_edge`.
std::vector<Vec> inset_loop(const std::vector<Vec>& corners, double distance, double least_edge = 1.0);
// Where the lines p + s·t and q + u·v meet (not parallel).
Vec meet(const Vec& p, const Vec& t, const Vec& q, const Vec& v);
// The direction 90 degrees counter-clockwise from t.
inline Vec left_of(const Vec& t) { return {-t.y(), t.x()}; }

// The least distance from p to the segment a-b.
double distance_to_segment(const Vec& p, const Vec& a, const Vec& b);
// The least distance between the segments a-b and c-d (0 when they cross).
double segment_distance(const Vec& a, const Vec& b, const Vec& c, const Vec& d);
// The least distance from the segment a-b to the path's legs.
double distance_to_path(const Vec& a, const Vec& b, const std::vector<Vec>& waypoints);

// The families (one file each: generated_rooms.cpp, generated_corridors.cpp,
// generated_office.cpp). Each draws from `rng` only and may return a layout that fails the
// checks; map_generator.cpp then draws again.
Layout convex_room(RandomSequence& rng);
Layout inner_walls_room(RandomSequence& rng, double clearance);
Layout clutter_room(RandomSequence& rng, double clearance);
Layout corridor(RandomSequence& rng, double clearance, bool mirrored);
Layout office(RandomSequence& rng);

}  // namespace relslam::sim::layout
