#include "map_layout.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace relslam::sim::layout {

void add_wall(Layout& layout, const Vec& a, const Vec& b, const Vec& facing, bool one_sided) {
  Wall wall = Wall::between(static_cast<int>(layout.walls.size()), a, b);
  if (wall.normal().dot(facing) < 0) std::swap(wall.a, wall.b);
  wall.one_sided = one_sided;
  layout.walls.push_back(wall);
}

std::vector<std::pair<double, double>> piece_positions(double s0, double s1, const PieceGrid& grid,
                                                       RandomSequence& rng) {
  std::vector<std::pair<double, double>> pieces;
  double s = s0 + 0.5 * rng.uniform(grid.gap_min, grid.gap_max);
  while (s < s1) {
    const double to = std::min(s + rng.uniform(grid.piece_min, grid.piece_max), s1);
    pieces.emplace_back(s, to);
    s = to + rng.uniform(grid.gap_min, grid.gap_max);
  }
  return pieces;
}

void add_pieces(Layout& layout, const Vec& origin, const Vec& direction,
                const std::vector<std::pair<double, double>>& pieces, double lo, double hi, const Vec& facing) {
  for (const auto& [from, to] : pieces) {
    const double a = std::max(from, lo), b = std::min(to, hi);
    if (b > a) add_wall(layout, origin + a * direction, origin + b * direction, facing);
  }
}

std::vector<Vec> convex_polygon(int n, double r, double min_gap, double max_gap, RandomSequence& rng) {
  // Gaps drawn around their mean and scaled to a full turn; a draw outside the bounds is drawn
  // again (a few tries; the caller draws a new layout when none fits).
  for (int attempt = 0; attempt < 50; ++attempt) {
    std::vector<double> gaps(static_cast<std::size_t>(n));
    double sum = 0;
    for (double& g : gaps) sum += g = rng.uniform(0.6, 1.4);
    const double scale = 2.0 * std::numbers::pi / sum;
    if (std::any_of(gaps.begin(), gaps.end(), [&](double g) { return g * scale < min_gap || g * scale > max_gap; }))
      continue;
    std::vector<Vec> corners;
    double angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
    for (double g : gaps) {
      corners.emplace_back(r * std::cos(angle), r * std::sin(angle));
      angle += g * scale;
    }
    return corners;
  }
  return {};
}

void add_polygon_walls(Layout& layout, const std::vector<Vec>& corners) {
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec& a = corners[i];
    const Vec& b = corners[(i + 1) % corners.size()];
    add_wall(layout, a, b, -0.5 * (a + b));  // towards the centre
  }
}

Vec meet(const Vec& p, const Vec& t, const Vec& q, const Vec& v) {
  const double det = t.x() * v.y() - t.y() * v.x();
  const Vec d = q - p;
  return p + ((d.x() * v.y() - d.y() * v.x()) / det) * t;
}

std::vector<Vec> inset_loop(const std::vector<Vec>& corners, double distance, double least_edge) {
  const std::size_t n = corners.size();
  const auto edge = [&](std::size_t i) { return (corners[(i + 1) % n] - corners[i]).normalized(); };
  std::vector<Vec> loop;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t before = (i + n - 1) % n;
    const Vec tp = edge(before), t = edge(i);
    loop.push_back(meet(corners[before] + distance * left_of(tp), tp, corners[i] + distance * left_of(t), t));
  }
  for (std::size_t i = 0; i < n; ++i)
    if ((loop[(i + 1) % n] - loop[i]).dot(edge(i)) < least_edge) return {};
  loop.push_back(loop.front());
  return loop;
}

double distance_to_segment(const Vec& p, const Vec& a, const Vec& b) {
  const Vec d = b - a;
  const double t = d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

namespace {
double cross(const Vec& u, const Vec& v) { return u.x() * v.y() - u.y() * v.x(); }
}  // namespace

double segment_distance(const Vec& a, const Vec& b, const Vec& c, const Vec& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return 0.0;
  return std::min({distance_to_segment(a, c, d), distance_to_segment(b, c, d), distance_to_segment(c, a, b),
                   distance_to_segment(d, a, b)});
}

double distance_to_path(const Vec& a, const Vec& b, const std::vector<Vec>& waypoints) {
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < waypoints.size(); ++i)
    least = std::min(least, segment_distance(a, b, waypoints[i], waypoints[i + 1]));
  return least;
}

}  // namespace relslam::sim::layout
