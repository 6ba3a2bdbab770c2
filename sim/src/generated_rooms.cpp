// The room families of the map generator (map_generator.hpp): convex rooms, rooms with an inner
// wall and pillars, rooms with clutter. Each is a convex polygon on a circle, walked as a loop on
// the same polygon moved inwards from its walls, twice (the second loop closes it).

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

// A convex room of `least` to `least + choices - 1` walls on a circle of radius r_lo..r_hi, the
// angles between neighbouring corners in min_gap..max_gap degrees, and its loop `inset` from the
// walls, walked twice.
struct RoomShape {
  int least = 4, choices = 5;
  double r_lo = 6.0, r_hi = 10.0;
  double min_gap_deg = 30.0, max_gap_deg = 100.0;
  double inset_lo = 1.8, inset_hi = 3.0;
};

struct Room {
  Layout layout;
  std::vector<Vec> corners;  // empty when none was found
  double r = 0.0;
};

Room draw_room(RandomSequence& rng, const RoomShape& shape, const char* what) {
  Room room;
  const int n = shape.least + static_cast<int>(rng.below(static_cast<std::uint64_t>(shape.choices)));
  room.r = rng.uniform(shape.r_lo, shape.r_hi);
  room.corners = convex_polygon(n, room.r, shape.min_gap_deg * kDegree, shape.max_gap_deg * kDegree, rng);
  const double inset = rng.uniform(shape.inset_lo, shape.inset_hi);
  if (room.corners.empty()) return room;
  add_polygon_walls(room.layout, room.corners);
  room.layout.waypoints = inset_loop(room.corners, inset);
  room.layout.loops = 2;
  room.layout.description = describe_room(what, n, room.r, inset);
  return room;
}

}  // namespace

Layout convex_room(RandomSequence& rng) { return draw_room(rng, {}, "Generated convex room").layout; }

// A point `inward` inside the loop from a random leg's middle part: where the small frustum
// (half-angle 30 degrees, far 7), looking along the leg, sees what stands there (a wall 2 beside
// the path is in view from 3.5 before it on).
Vec beside_a_leg(RandomSequence& rng, const std::vector<Vec>& loop, double inward) {
  const std::size_t leg = rng.below(loop.size() - 1);
  const Vec& p = loop[leg];
  const Vec& q = loop[leg + 1];
  return p + rng.uniform(0.3, 0.7) * (q - p) + inward * left_of(q - p).normalized();
}

Layout inner_walls_room(RandomSequence& rng, double clearance) {
  Room room = draw_room(rng, {5, 4, 8.0, 11.0, 30.0, 90.0, 2.0, 2.8}, "Generated room with an inner wall and pillars");
  if (room.corners.empty() || room.layout.waypoints.empty()) return {};
  Layout& l = room.layout;
  // The inner wall, seen from both sides, beside one leg; then the pillars beside others.
  bool inner = false;
  for (int tries = 0; !inner && tries < 20; ++tries) {
    const Vec c = beside_a_leg(rng, l.waypoints, rng.uniform(1.6, 2.6));
    const auto [a, b] = segment_at(c, rng.uniform(1.5, 3.0), rng.uniform(0.0, std::numbers::pi));
    if (distance_to_path(a, b, l.waypoints) < clearance + 0.25 || !keeps_apart(l, a, b, 0.5)) continue;
    add_wall(l, a, b, Vec(0, 1), false);
    inner = true;
  }
  if (!inner) return {};
  const int pillars = 1 + static_cast<int>(rng.below(2));
  int placed = 0;
  for (int tries = 0; placed < pillars && tries < 20; ++tries) {
    const double side = rng.uniform(0.8, 1.5);
    const Vec c = beside_a_leg(rng, l.waypoints, rng.uniform(1.3, 2.0) + 0.75 * side);
    const double angle = rng.uniform(0.0, std::numbers::pi / 2);
    // The pillar's corners are at most side/sqrt(2) from its centre.
    if (distance_to_path(c, c, l.waypoints) < clearance + 0.25 + 0.75 * side || !keeps_apart(l, c, c, side + 0.5))
      continue;
    add_pillar(l, c, side, angle);
    ++placed;
  }
  l.description += "; a two-sided inner wall and " + std::to_string(placed) + " square pillar(s) beside the path";
  return l;
}

Layout clutter_room(RandomSequence& rng, double clearance) {
  Room room = draw_room(rng, {4, 3, 8.0, 11.0, 40.0, 100.0, 3.0, 3.6}, "Generated room with clutter");
  if (room.corners.empty()) return {};
  Layout& l = room.layout;
  const std::vector<Vec>& corners = room.corners;
  // Short two-sided walls at any angle in the band between the path and the room's walls.
  const int wanted = 6 + static_cast<int>(rng.below(5));
  int placed = 0;
  for (int tries = 0; placed < wanted && tries < 200; ++tries) {
    const std::size_t e = rng.below(corners.size());
    const Vec& p = corners[e];
    const Vec& q = corners[(e + 1) % corners.size()];
    const Vec c = p + rng.uniform(0.15, 0.85) * (q - p) + rng.uniform(0.6, 1.6) * left_of(q - p).normalized();
    const auto [a, b] = segment_at(c, rng.uniform(0.6, 1.4), rng.uniform(0.0, std::numbers::pi));
    if (distance_to_path(a, b, l.waypoints) < clearance + 0.25 || !keeps_apart(l, a, b, 0.3)) continue;
    add_wall(l, a, b, Vec(0, 1), false);
    ++placed;
  }
  l.description += "; " + std::to_string(placed) + " short two-sided clutter walls between the path and the walls";
  return l;
}

}  // namespace relslam::sim::layout
