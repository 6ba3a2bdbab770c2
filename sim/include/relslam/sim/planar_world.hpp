#pragma once
// The planar world: vertical, infinitely thin walls of constant height on a flat floor
// (thesis 4.4.2.4 `PlaneManager`). Part of relslam/sim: Eigen only.

#include "relslam/core/option_issue.hpp"

#include <Eigen/Core>

#include <vector>

namespace relslam::sim {

// Iterations first..last, both included.
struct IterationWindow {
  int first = 0;
  int last = 0;
  bool contains(int k) const { return first <= k && k <= last; }
};

// One wall in world (x, z). Invariant (checked by check()): a != b, so the front normal
// n = Rot(+90°)(b − a)/|b − a| is defined; it points to the side the wall is seen from.
struct Wall {
  int id = 0;  // unique, >= 0; the truth tag of every plane this wall produces
  Eigen::Vector2d a = Eigen::Vector2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::UnitX();
  // The walls' height is static in the thesis's simulator [T 4.2.3]; the value is [R].
  double height = 2.5;
  // A one-sided wall has only its front; with back-face culling on it is invisible from
  // behind. A two-sided wall is always seen, with the face that looks at the robot [R].
  bool one_sided = true;
  // For the scripted sensor only: the iterations in which the wall is reported, at full size
  // (the thesis's `RltMapBuilderUnitTest` table of Fig. 71, thesis 4.4.2) [T].
  std::vector<IterationWindow> scripted_windows;

  // A one-sided wall of the default height from a to b (front on the left of a→b).
  static Wall between(int id, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    Wall w;
    w.id = id;
    w.a = a;
    w.b = b;
    return w;
  }

  Eigen::Vector2d tangent() const { return (b - a).normalized(); }
  Eigen::Vector2d normal() const {
    const Eigen::Vector2d u = tangent();
    return {-u.y(), u.x()};
  }
  double length() const { return (b - a).norm(); }
  // True when p lies strictly on the front side (the back-face test).
  bool faces(const Eigen::Vector2d& p) const { return normal().dot(p - a) > 0.0; }
  // Whether the wall may be seen from behind: back-face culling is off, or the wall is
  // two-sided (shared by the plane and the point sensor).
  bool seen_from_both_sides(bool backface_cull) const { return !backface_cull || !one_sided; }
  // Whether a viewer at p (world) sees a face of the wall at all.
  bool visible_from(const Eigen::Vector2d& p, bool backface_cull) const {
    return seen_from_both_sides(backface_cull) || faces(p);
  }
};

// True when the segment p→q crosses the wall a→b (world (x, z)). A wall only touched by the
// segment's end p (the point lies on that wall) or lying on the same line does not block it:
// walls are infinitely thin and span their whole height, so this 2D test is the exact
// occlusion test of the point sensor (thesis 2.4: "a ray is projected from the point's
// location to the robot viewpoint").
bool segment_crosses_wall(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Wall& wall);

// The map. Its order is the sensor's output order: the thesis's comparison order inside X0
// followed the order in which the simulator stored planes 1–5 (Fig. 94) [T].
struct PlanarWorld {
  std::vector<Wall> walls;
};

// Every violated constraint; fields name the wall by its position: "walls[3].b".
std::vector<OptionIssue> check(const PlanarWorld& world);

}  // namespace relslam::sim
