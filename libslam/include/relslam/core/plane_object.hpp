#pragma once
// One observed vertical plane (a wall, or the visible part of one) and one iteration's planes:
// what the Relative Plane algorithm may see (thesis 4.1, 4.4 `PlaneObject`).
// Part of relslam/core: Eigen only. Truth travels separately, in
// PlaneTruthFrame, which only the evaluation reads.

#include "relslam/core/laser_scan.hpp"
#include "relslam/core/planar_pose.hpp"

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <vector>

namespace relslam {

// A plane in the frame it was observed in (the robot frame at its iteration, robot at the
// origin facing +x). Its top corners `a` and `b` are ordered so that the unit normal
// n = Rot(+90°)(b − a)/|b − a| points to the front, visible side: rotated by −θ the plane lies
// along +x with its normal along +z, `a` is the left end (key point 1) and `b` the right end
// (key point 2) (thesis Rule 14).
struct PlaneObject {
  Eigen::Vector2d a = Eigen::Vector2d::Zero();   // key point 1, (x, z)
  Eigen::Vector2d b = Eigen::Vector2d::UnitX();  // key point 2, (x, z)
  double y_lo = 0.0;                             // height range; the walls' height is static [T]
  double y_hi = 2.5;
  int iteration = 0;
  // The sensor cut this end at the edge of its field of view: it is where the view ends, not
  // where the wall ends, so it slides as the robot moves (thesis 4.3.4: only a static end is a
  // key point). False where the sensor does not say (the thesis's sensor reports no such flag).
  bool a_cut = false;
  bool b_cut = false;

  Eigen::Vector2d tangent() const { return (b - a).normalized(); }
  Eigen::Vector2d normal() const {
    const Eigen::Vector2d u = tangent();
    return {-u.y(), u.x()};
  }
  // θ = atan2(u_z, u_x).
  double angle() const;
  Eigen::Vector2d midpoint() const { return 0.5 * (a + b); }
  double length() const { return (b - a).norm(); }
  double height() const { return y_hi - y_lo; }
  // d = −n·m: n·p + d = 0 on the plane; d > 0 is the distance of the origin in front of it.
  double offset() const { return -normal().dot(midpoint()); }
  // P = (m, θ): the plane's frame (origin at the midpoint, +x along the plane, +z its normal).
  PlanarPose pose() const { return {midpoint(), angle()}; }

  // The plane of `length` centred at pose (m, θ): a = m − (L/2)u(θ), b = m + (L/2)u(θ).
  static PlaneObject from_pose(const PlanarPose& pose, double length, double y_lo = 0.0, double y_hi = 2.5,
                               int iteration = 0);
  // The same plane seen from another frame: both ends mapped by a_T_b (from b's frame to a's).
  PlaneObject transformed(const PlanarPose& a_T_b) const;
};

// One iteration's planes, in the sensor's output order (map order, deterministic, as the thesis's simulator: Fig. 94).
struct PlaneFrame {
  int iteration = 0;
  std::vector<PlaneObject> planes;
  // The raw 2-D scan the planes were extracted from, where they came from a planar laser
  // (baselines that match scans, such as ICP-SLAM, read it); null otherwise.
  std::shared_ptr<const LaserScan> scan;
  // The robot's motion since the previous frame by its odometry (previous_T_current), where
  // the recording has one; no algorithm of the thesis reads it.
  std::optional<PlanarPose> odometry = std::nullopt;
};

// What the simulator knows of one observed plane, for scoring only.
struct PlaneTruth {
  int wall_id = -1;           // the true wall (-1 unknown)
  bool a_is_wall_end = true;  // key point 1 is the wall's real end (false: cut by the frustum)
  bool b_is_wall_end = true;  // key point 2 likewise
};

// Truth that accompanies a PlaneFrame; planes[i] belongs to PlaneFrame::planes[i].
struct PlaneTruthFrame {
  int iteration = 0;
  PlanarPose world_T_robot;
  std::vector<PlaneTruth> planes;
  bool pose_known = true;  // false for recorded planes without a true path: no pose is scored
};

}  // namespace relslam
