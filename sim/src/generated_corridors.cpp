// The corridor families of the map generator (map_generator.hpp): L, T and U corridors with a
// dead end at every end, their sides cut into pieces with gaps (doors), walked out and back with
// a 180° turn at each dead end. Mirrored: both sides cut by one grid, so that pieces face each
// other in pairs of equal length (the ties of thesis Rule 15, as Map B's hallway).

#include "map_layout.hpp"

#include <cmath>
#include <numbers>

namespace relslam::sim::layout {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// How the corridor's sides are cut: one grid for both sides when mirrored, else one each.
struct Cutter {
  RandomSequence& rng;
  bool mirrored;
  PieceGrid grid;
  std::vector<std::pair<double, double>> shared;

  std::vector<std::pair<double, double>> pieces(double s0, double s1) {
    if (!mirrored) return piece_positions(s0, s1, grid, rng);
    if (shared.empty()) shared = piece_positions(s0, s1, grid, rng);
    return shared;
  }
};

Cutter cutter_for(RandomSequence& rng, bool mirrored) {
  if (!mirrored) return {rng, false, {2.5, 5.0, 0.5, 1.2}, {}};
  const double piece = rng.uniform(3.0, 4.5), gap = rng.uniform(0.8, 1.2);
  return {rng, true, {piece, piece, gap, gap}, {}};
}

void add_cap(Layout& l, const Vec& p, const Vec& inwards, double half_width) {
  const Vec n = left_of(inwards);
  add_wall(l, p + half_width * n, p - half_width * n, inwards);
}

// L (one turn) or U (two turns the same way): a centre line of legs joined at mitred corners.
void bent_corridor(Layout& l, RandomSequence& rng, Cutter& cut, double h, double margin, bool u_shape) {
  std::vector<Vec> centre = {Vec::Zero()};
  double heading = 0.0;
  const double side = rng.uniform() < 0.5 ? 1.0 : -1.0;
  const int legs = u_shape ? 3 : 2;
  for (int i = 0; i < legs; ++i) {
    const double length = u_shape && i == 1 ? rng.uniform(7.0, 10.0) : rng.uniform(10.0, 18.0);
    centre.push_back(centre.back() + length * Vec(std::cos(heading), std::sin(heading)));
    heading += side * rng.uniform(75.0, 105.0) * kDegree;
  }
  for (std::size_t i = 0; i + 1 < centre.size(); ++i) {
    cut.shared.clear();  // a mirrored grid is shared by the two sides of one leg
    const Vec t = (centre[i + 1] - centre[i]).normalized(), n = left_of(t);
    for (const double sigma : {1.0, -1.0}) {
      const Vec origin = centre[i] + sigma * h * n;
      Vec from = origin, to = centre[i + 1] + sigma * h * n;
      if (i > 0) {
        const Vec tp = (centre[i] - centre[i - 1]).normalized();
        from = meet(centre[i - 1] + sigma * h * left_of(tp), tp, origin, t);
      }
      if (i + 2 < centre.size()) {
        const Vec tn = (centre[i + 2] - centre[i + 1]).normalized();
        to = meet(origin, t, centre[i + 1] + sigma * h * left_of(tn), tn);
      }
      const double s0 = (from - origin).dot(t), s1 = (to - origin).dot(t);
      add_pieces(l, origin, t, cut.pieces(-2.0 * h, (centre[i + 1] - centre[i]).norm() + 2.0 * h), s0, s1,
                 -sigma * n);
    }
  }
  const Vec t0 = (centre[1] - centre[0]).normalized();
  const Vec tn = (centre.back() - centre[centre.size() - 2]).normalized();
  add_cap(l, centre.front(), t0, h);
  add_cap(l, centre.back(), -tn, h);
  // Out to the far dead end and back.
  std::vector<Vec> out = centre;
  out.front() += margin * t0;
  out.back() -= margin * tn;
  l.waypoints = out;
  for (auto it = out.rbegin() + 1; it != out.rend(); ++it) l.waypoints.push_back(*it);
}

// T: a straight corridor along x with a branch up +z from its middle, walked from the branch's
// dead end to each end of the main corridor and back.
void t_corridor(Layout& l, RandomSequence& rng, Cutter& cut, double h, double margin) {
  const double left = rng.uniform(8.0, 15.0), right = rng.uniform(8.0, 15.0), up = rng.uniform(8.0, 14.0);
  const Vec x(1, 0), z(0, 1);
  const auto main = cut.pieces(-left, right);
  add_pieces(l, Vec(0, -h), x, main, -left, right, z);
  add_pieces(l, Vec(0, h), x, cut.mirrored ? main : cut.pieces(-left, right), -left, -h, -z);
  add_pieces(l, Vec(0, h), x, cut.mirrored ? main : cut.pieces(-left, right), h, right, -z);
  cut.shared.clear();
  add_pieces(l, Vec(-h, 0), z, cut.pieces(h, up), h, up, x);
  add_pieces(l, Vec(h, 0), z, cut.pieces(h, up), h, up, -x);
  add_cap(l, Vec(-left, 0), x, h);
  add_cap(l, Vec(right, 0), -x, h);
  add_cap(l, Vec(0, up), -z, h);
  const Vec start(0, up - margin);
  l.waypoints = {start, Vec::Zero(), Vec(-left + margin, 0), Vec(right - margin, 0), Vec::Zero(), start};
}

}  // namespace

Layout corridor(RandomSequence& rng, double clearance, bool mirrored) {
  Layout l;
  const double width = rng.uniform(2.5, 3.5), h = 0.5 * width;
  const double margin = clearance + 0.25;  // the robot turns this far before a dead end
  Cutter cut = cutter_for(rng, mirrored);
  const int shape = static_cast<int>(rng.below(3));
  const char* names[] = {"L", "T", "U"};
  if (shape == 1)
    t_corridor(l, rng, cut, h, margin);
  else
    bent_corridor(l, rng, cut, h, margin, shape == 2);
  l.loops = 1;
  l.description = std::string("Generated ") + names[shape] + "-shaped corridor of width " +
                  format_number(std::round(width * 100) / 100) + " with a dead end at each end, its sides cut into " +
                  (mirrored ? "pieces mirroring each other across the corridor" : "pieces of 2.5-5 with gaps") +
                  "; walked out to every dead end and back (a 180-degree turn at each)";
  return l;
}

}  // namespace relslam::sim::layout
