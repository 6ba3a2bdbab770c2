#include "relslam/sim/planar_world.hpp"
#include "relslam/core/option_fields.hpp"

#include <cmath>
#include <map>
#include <string>

namespace relslam::sim {
namespace {

std::string point_text(const Eigen::Vector2d& p) {
  return "[" + format_number(p.x()) + ", " + format_number(p.y()) + "]";
}

// > 0 when c lies to the left of a→b, < 0 to the right, 0 on the line.
double orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const Eigen::Vector2d u = b - a, v = c - a;
  return u.x() * v.y() - u.y() * v.x();
}

}  // namespace

bool segment_crosses_wall(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Wall& wall) {
  // The wall's ends on opposite sides of the line p→q (or one on it: a ray through a wall's
  // end is blocked), and p and q strictly on opposite sides of the wall's line.
  const double wall_a = orientation(p, q, wall.a), wall_b = orientation(p, q, wall.b);
  if (wall_a * wall_b > 0.0) return false;
  const double side_p = orientation(wall.a, wall.b, p), side_q = orientation(wall.a, wall.b, q);
  return side_p * side_q < 0.0;
}

std::vector<OptionIssue> check(const PlanarWorld& world) {
  std::vector<OptionIssue> issues;
  std::map<int, std::size_t> first_with_id;
  for (std::size_t i = 0; i < world.walls.size(); ++i) {
    const Wall& w = world.walls[i];
    const std::string field = "walls[" + std::to_string(i) + "]";
    bool ends_finite = true;
    for (const auto& [name, p] : {std::pair{"a", w.a}, std::pair{"b", w.b}}) {
      if (p.allFinite()) continue;
      issues.push_back({field + "." + name, "must be a finite point, got " + point_text(p)});
      ends_finite = false;
    }
    // A zero-length wall has no tangent, hence no normal and no front.
    if (ends_finite && w.a == w.b)
      issues.push_back({field + ".b", "equals a " + point_text(w.a) + "; a wall needs two distinct ends"});
    above(0.0)(issues, field + ".height", w.height);
    if (w.id < 0) issues.push_back({field + ".id", "must be >= 0, got " + std::to_string(w.id)});
    const auto [it, fresh] = first_with_id.emplace(w.id, i);
    if (!fresh)
      issues.push_back(
          {field + ".id", "repeats the id " + std::to_string(w.id) + " of walls[" + std::to_string(it->second) + "]"});
    for (std::size_t j = 0; j < w.scripted_windows.size(); ++j) {
      const IterationWindow& window = w.scripted_windows[j];
      if (window.first < 0 || window.last < window.first)
        issues.push_back({field + ".scripted_windows[" + std::to_string(j) + "]",
                          "must be [first, last] with 0 <= first <= last, got [" + std::to_string(window.first) + ", " +
                              std::to_string(window.last) + "]"});
    }
  }
  return issues;
}

}  // namespace relslam::sim
