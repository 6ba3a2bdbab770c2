#pragma once
// A finished EM plane's rendering rectangle: the four corners the Relative Plane algorithm gets
// (thesis 3.5.2 step 11, 3.5.3 step 10; "Oriented rendering rectangle", A9). Eigen only.

#include <Eigen/Core>

#include <span>

namespace relslam::em {

// A rectangle standing on the floor plane's (x, z) line origin + s·tangent, s in [s_min, s_max],
// from y_min to y_max. tangent is the unit horizontal tangent u = (n_z, −n_x) of the plane's
// normal n (thesis 4.2.1), so s grows from key point 1 to key point 2.
struct OrientedRectangle {
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  // (x, z)
  Eigen::Vector2d tangent = Eigen::Vector2d::UnitX();
  double s_min = 0.0, s_max = 0.0;
  double y_min = 0.0, y_max = 0.0;

  Eigen::Vector2d at(double s) const { return origin + s * tangent; }
  double length() const { return s_max - s_min; }
};

// The unit horizontal tangent u = (n_z, −n_x)/|·| of a normal (thesis 4.2.1); +x for a horizontal
// plane, which has none.
Eigen::Vector2d horizontal_tangent(const Eigen::Vector3d& normal);

// The points' extent along the fitted plane's horizontal tangent and along y, the line through
// the centroid: a simplification, exact for vertical walls [R].
OrientedRectangle tangent_rectangle(std::span<const Eigen::Vector3d> points, std::span<const int> indices,
                                    const Eigen::Vector3d& normal, const Eigen::Vector3d& centroid);

// The thesis's EM2 search (3.5.3 step 10): the points' bounding box turned about y through
// 180°, scored at each angle by Σ over points of the distance (in x, z) to the nearest of the
// box's four edge lines, the box shrunk to the points at every angle; coarse to fine (`passes`
// passes, the first in steps of `step_rad`, each later one ±one step of the one before at a
// tenth of its step). The box side along which the points spread more is the plane's tangent.
OrientedRectangle search_rectangle(std::span<const Eigen::Vector3d> points, std::span<const int> indices,
                                   const Eigen::Vector3d& normal, const Eigen::Vector3d& centroid, double step_rad,
                                   int passes);

// The thesis's EM1 rule (3.5.2 step 11): of the 8 corners of the points' axis-aligned box, the
// 4 closest to the plane n·p + d = 0 (and any as close as the fourth), expressed along the
// tangent through the centroid.
OrientedRectangle box_corner_rectangle(std::span<const Eigen::Vector3d> points, std::span<const int> indices,
                                       const Eigen::Vector3d& normal, const Eigen::Vector3d& centroid);

}  // namespace relslam::em
