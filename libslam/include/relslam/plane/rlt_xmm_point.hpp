#pragma once
// RltXMMPoint (thesis 4.3.6, 4.4.3.3): the motion-model group. When only one
// partial plane is in view there is no key point in the current interval and so no pose
// (Rule 26); the plane's place is already known, only how far it extends is not (Rule 23). The
// motion model fixes its frame at the last valid pose (Rule 27) and tracks the robot from that
// one plane under a forward-only motion model (Rules 24, 25), growing the plane as more of it
// comes into view.

#include "relslam/core/planar_pose.hpp"
#include "relslam/plane/ids.hpp"
#include "relslam/plane/options.hpp"
#include "relslam/plane/rlt_plane.hpp"

#include <optional>
#include <vector>

namespace relslam::plane {

// The tracked robot at one iteration, in the motion model's frame (the anchor).
struct MotionModelSample {
  int iteration = 0;
  PlanarPose mm_T_robot;
  double distance = 0;      // D: the robot's distance to the plane's line
  double delta_normal = 0;  // Δ_n: motion towards the plane since the previous sample
  double delta_tangent = 0; // Δ_t: motion along it (0 under Rule 25)
};

// Invariant: the group `xpoint` holds exactly `plane`, whose membership pose is the plane in the
// anchor's frame at its tracked extent [s_min, s_max] along its tangent, as of the last
// compute(). A motion model is never reused: entering one always creates a new one [T].
class RltXMMPoint {
 public:
  // CreateMotionModelXPoint (Rule 27): the frame is world_T_anchor, the last valid pose, seen at
  // `start_iteration`; `world_plane` is where the map has the plane (its extent is the start).
  RltXMMPoint(XPointId xpoint, PlaneId plane, const PlanarPose& world_T_anchor, int start_iteration,
              const PlaneObject& world_plane);

  XPointId xpoint() const { return xpoint_; }
  PlaneId plane() const { return plane_; }
  const PlanarPose& anchor() const { return world_T_anchor_; }
  int start_iteration() const { return start_iteration_; }

  // ComputeXPoint for the motion model (Rules 23–25, thesis 4.3.6): re-runs the track over every
  // stored observation of the plane from the start, so it depends only on the observations
  // (deterministic replay), and writes the grown plane into its membership of this group.
  void compute(std::vector<RltPlane>& planes, const MotionModelOptions& options);

  // The motion model ended at `iteration` (its group stopped being the current one): its track,
  // and so the plane's extent, stay as they were then; later observations belong to others.
  void end(int iteration) { end_iteration_ = iteration; }
  bool ended() const { return end_iteration_ >= 0; }

  // The tracked robot at `iteration` in the world (anchor ∘ R(t)); none when the plane was not
  // seen then.
  std::optional<PlanarPose> world_T_robot(int iteration) const;
  // The last sample of the track (none before the first compute()).
  const MotionModelSample* last() const { return track_.empty() ? nullptr : &track_.back(); }
  // No step of the track dropped the motion along the plane (Rule 25: heading nearly parallel to
  // it) without a real end in view to measure it (MotionModelOptions::real_end_motion, off: no
  // end measures it): driving along a wall cut at both ends by the frustum, nothing shows how far
  // the robot went. Read by the adaptive preset only (its pose check and MapPlane::grounded); the
  // thesis's track is the same either way.
  bool along_observed() const { return along_observed_; }
  // The plane's tracked extent along its tangent, from its map midpoint at the start.
  double s_min() const { return s_min_; }
  double s_max() const { return s_max_; }

 private:
  // The membership of compute's track: the plane at its tracked extent, its key point the end
  // that did not move (grew_min, grew_max: which ends Rule 23 grew).
  void fill_membership(std::vector<RltPlane>& planes, bool grew_min, bool grew_max) const;
  XPointId xpoint_;
  PlaneId plane_;
  PlanarPose world_T_anchor_;
  int start_iteration_;
  int end_iteration_ = -1;  // -1 while active
  PlanarPose mm_T_plane_;  // the plane's midpoint frame at the start, in the anchor frame
  double start_min_, start_max_;
  bool along_observed_ = true;
  double s_min_ = 0, s_max_ = 0;
  std::vector<MotionModelSample> track_;
};

}  // namespace relslam::plane
