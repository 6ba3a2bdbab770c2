// The office family of the map generator (map_generator.hpp): Map D's office loop (thesis Figs
// 67, 73-82) at a random size, corridor width, piece lengths and rotation. A corridor runs round
// an inner block inside an outer rectangle, every side cut into pieces with gaps; the robot drives
// one loop and the legs that close it, as on Map D.

#include "map_layout.hpp"

#include <cmath>

namespace relslam::sim::layout {
namespace {

// The sides of the rectangle [0, w] x [0, h], each cut into pieces and facing `sign` times inwards
// (+1: the outer walls, seen from inside; -1: the inner block, seen from outside).
void add_rectangle(Layout& l, const Vec& low, const Vec& high, double sign, const PieceGrid& grid,
                   RandomSequence& rng) {
  const Vec corners[] = {low, Vec(high.x(), low.y()), high, Vec(low.x(), high.y())};
  const Vec centre = 0.5 * (low + high);
  for (int i = 0; i < 4; ++i) {
    const Vec& a = corners[i];
    const Vec& b = corners[(i + 1) % 4];
    const double length = (b - a).norm();
    const Vec t = (b - a) / length;
    const Vec facing = sign * (centre - 0.5 * (a + b));
    add_pieces(l, a, t, piece_positions(0.0, length, grid, rng), 0.0, length, facing);
  }
}

}  // namespace

Layout office(RandomSequence& rng) {
  Layout l;
  const double w = rng.uniform(24.0, 34.0), h = rng.uniform(16.0, 22.0), c = rng.uniform(2.5, 3.5);
  const PieceGrid grid{3.0, 5.0, 0.6, 1.2};
  add_rectangle(l, Vec(0, 0), Vec(w, h), 1.0, grid, rng);
  add_rectangle(l, Vec(c, c), Vec(w - c, h - c), -1.0, grid, rng);
  const double m = 0.5 * c;  // the corridor's middle
  l.waypoints = {Vec(0.5 * w, m), Vec(w - m, m), Vec(w - m, h - m), Vec(m, h - m), Vec(m, m), Vec(0.5 * w, m)};
  l.loops = 1;
  l.closing_legs = 2;  // past the first corner again: the loop is closed (as Map D's "then")
  l.description = "Generated office: Map D's loop at " + format_number(std::round(w * 10) / 10) + " x " +
                  format_number(std::round(h * 10) / 10) + ", corridor width " +
                  format_number(std::round(c * 100) / 100) + ", every side cut into pieces of 3-5 with gaps of " +
                  "0.6-1.2, one loop and two legs more, at a random rotation";
  return l;
}

}  // namespace relslam::sim::layout
