// The room families of the map generator (map_generator.hpp): convex rooms, rooms with an inner
// wall and pillars, rooms with clutter. Each is a convex polygon on a circle, walked as a loop on
// the same polygon scaled towards its centre, twice (the second loop closes it).

#include "map_layout.hpp"

#include <cmath>
#include <numbers>

namespace relslam::sim::layout {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

std::string describe_room(const char* what, int corners, double r, double inset) {
  return std::string(what) + ": a convex room of " + std::to_string(corners) + " walls on a circle of radius " +
         format_number(std::round(r * 100) / 100) + ", walked twice round a loop " +
         format_number(std::round(inset * 100) / 100) + " inside its walls";
}

// A square pillar of side `side` centred at c, its faces outwards (clockwise corners).
void add_pillar(Layout& l, const Vec& c, double side, double angle) {
  const Vec u(std::cos(angle), std::sin(angle)), v(-u.y(), u.x());
  const Vec h = 0.5 * side * u, k = 0.5 * side * v;
  const Vec corners[] = {c + h + k, c - h + k, c - h - k, c + h - k};
  for (int i = 0; i < 4; ++i) {
    const Vec& a = corners[i];
    const Vec& b = corners[(i + 1) % 4];
    add_wall(l, a, b, 0.5 * (a + b) - c);
  }
}

// A short wall centred at c, of length `length` along `angle`.
std::pair<Vec, Vec> segment_at(const Vec& c, double length, double angle) {
  const Vec u = 0.5 * length * Vec(std::cos(angle), std::sin(angle));
  return {c - u, c + u};
}

// Whether the segment a-b keeps `gap` from every wall already placed.
bool keeps_apart(const Layout& l, const Vec& a, const Vec& b, double gap) {
  for (const Wall& w : l.walls)
    if (segment_distance(a, b, w.a, w.b) < gap) return false;
  return true;
}

}  // namespace

Layout convex_room(RandomSequence& rng) {
  Layout l;
  const int n = 4 + static_cast<int>(rng.below(5));
  const double r = rng.uniform(6.0, 10.0);
  const std::vector<Vec> corners = convex_polygon(n, r, 30 * kDegree, 100 * kDegree, rng);
  const double inset = rng.uniform(1.8, 3.0);
  if (corners.empty()) return l;
  add_polygon_walls(l, corners);
  l.waypoints = inset_loop(corners, inset);
  l.loops = 2;
  l.description = describe_room("Generated convex room", n, r, inset);
  return l;
}

Layout inner_walls_room(RandomSequence& rng) {
  Layout l;
  const int n = 5 + static_cast<int>(rng.below(4));
  const double r = rng.uniform(8.0, 11.0);
  const std::vector<Vec> corners = convex_polygon(n, r, 30 * kDegree, 90 * kDegree, rng);
  const double inset = rng.uniform(2.0, 2.8);
  if (corners.empty()) return l;
  add_polygon_walls(l, corners);
  // The inner wall near the centre, seen from both sides; then the pillars beside it.
  const Vec centre = 0.08 * r * Vec(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
  const auto [a, b] = segment_at(centre, rng.uniform(0.15, 0.3) * r, rng.uniform(0.0, std::numbers::pi));
  add_wall(l, a, b, Vec(0, 1), false);
  const int pillars = 1 + static_cast<int>(rng.below(2));
  for (int placed = 0, tries = 0; placed < pillars && tries < 20; ++tries) {
    const double side = rng.uniform(0.8, 1.5);
    const double angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
    const Vec c = rng.uniform(0.15, 0.25) * r * Vec(std::cos(angle), std::sin(angle));
    if (!keeps_apart(l, c, c, side + 1.0)) continue;
    add_pillar(l, c, side, rng.uniform(0.0, std::numbers::pi / 2));
    ++placed;
  }
  l.waypoints = inset_loop(corners, inset);
  l.loops = 2;
  l.description = describe_room("Generated room with an inner wall and pillars", n, r, inset) +
                  "; a two-sided inner wall and " + std::to_string(pillars) + " square pillar(s) near the centre";
  return l;
}

Layout clutter_room(RandomSequence& rng, double clearance) {
  Layout l;
  const int n = 4 + static_cast<int>(rng.below(3));
  const double r = rng.uniform(8.0, 11.0);
  const std::vector<Vec> corners = convex_polygon(n, r, 40 * kDegree, 100 * kDegree, rng);
  const double inset = rng.uniform(3.0, 3.6);
  if (corners.empty()) return l;
  add_polygon_walls(l, corners);
  l.waypoints = inset_loop(corners, inset);
  // Short two-sided walls at any angle in the band between the path and the room's walls.
  const int wanted = 6 + static_cast<int>(rng.below(5));
  int placed = 0;
  for (int tries = 0; placed < wanted && tries < 200; ++tries) {
    const std::size_t e = rng.below(corners.size());
    const Vec& p = corners[e];
    const Vec& q = corners[(e + 1) % corners.size()];
    const Vec inward = Vec(-(q - p).y(), (q - p).x()).normalized();  // counter-clockwise corners
    const Vec c = p + rng.uniform(0.15, 0.85) * (q - p) + rng.uniform(0.6, 1.6) * inward;
    const auto [a, b] = segment_at(c, rng.uniform(0.6, 1.4), rng.uniform(0.0, std::numbers::pi));
    if (distance_to_path(a, b, l.waypoints) < clearance + 0.25 || !keeps_apart(l, a, b, 0.3)) continue;
    add_wall(l, a, b, Vec(0, 1), false);
    ++placed;
  }
  l.loops = 2;
  l.description = describe_room("Generated room with clutter", n, r, inset) + "; " + std::to_string(placed) +
                  " short two-sided clutter walls between the path and the walls";
  return l;
}

}  // namespace relslam::sim::layout
