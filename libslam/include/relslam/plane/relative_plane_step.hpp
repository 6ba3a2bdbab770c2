#pragma once
// What one iteration of the Relative Plane algorithm produced (RltXPointsS::step), with the
// Profiler's part timings (thesis 4.4.2.5) and the roll-back counts (Rules 31–34): a value the
// sequencer and its stages both fill, in its own header below both.

#include "relslam/core/planar_pose.hpp"
#include "relslam/plane/ids.hpp"
#include "relslam/plane/rlt_map_builder.hpp"
#include "relslam/plane/rlt_xmm_point.hpp"
#include "relslam/plane/rlt_xpoint.hpp"
#include "relslam/plane/rlt_xpoint_link.hpp"
#include "relslam/plane/roll_back.hpp"

#include <span>

namespace relslam::plane {

// Wall time of the thesis's parts of one iteration (the Profiler of 4.4.2.5), milliseconds.
struct PlaneStepTimings {
  double add_ms = 0;      // AddPlane: registration (Rules 1, 10, 11)
  double manage_ms = 0;   // ManageXPoints: grouping and linking (Rules 7–9, 12)
  double compute_ms = 0;  // ComputeXPoints: pairwise comparisons and chaining (Rules 2, 3, 6)
  double build_ms = 0;    // BuildMap (Rules 4, 6, 8)
  double pose_ms = 0;     // GetPoset (Rule 5)
  // RollBack (Rule 33): restoring and replaying, the replayed iterations whole. The parts above
  // are those of the iteration's first run.
  double roll_back_ms = 0;
  double total_ms() const { return add_ms + manage_ms + compute_ms + build_ms + pose_ms + roll_back_ms; }
};

// Rules 31–34 in one step (replays included).
struct RollBackCounts {
  int hints = 0;                // hints sent back (Rule 32)
  int rollbacks = 0;            // roll-backs restored and replayed (Rule 33)
  int refused = 0;              // requests refused: too old or nested too deep
  int replayed_iterations = 0;  // iterations run again
};

// What one iteration produced. The spans point into the algorithm and stay valid until the
// next step() (no copy per iteration).
struct RelativePlaneStep {
  int iteration = 0;
  PlanarPose world_T_robot;  // meaningful only when pose_valid
  bool pose_valid = false;
  int pose_planes = 0;                  // observations the pose came from
  // Adaptive preset: why the pose is (in)valid (pose_integrity.hpp).
  PoseReason pose_reason = PoseReason::NoPlanes;
  std::span<const PlaneId> assignment;  // the RltPlane of each observation, in input order
  std::span<const MapPlane> map;        // one entry per RltPlane (MapPlane::mapped says if placed)
  std::span<const RltXPoint> groups;
  std::span<const RltXPointLink> links;
  XPointId current_group = kNone;
  int new_planes = 0;      // RltPlanes created
  int local_matches = 0;   // observations registered against a previous observation (Rule 1)
  int global_matches = 0;  // ... through the map and the previous pose (Rule 11)
  int groups_created = 0;
  int planes_grouped = 0;  // unassigned planes that joined or started a group
  int groups_computed = 0;
  int oneway_links = 0;  // Rule 37's one-way links added
  // The motion model carrying the pose this iteration (Rules 23–27), or nullptr.
  const RltXMMPoint* motion_model = nullptr;
  PlaneStepTimings timings;
  // Rules 31–34: what this step's interval checks and roll-backs did; after a roll-back every
  // field above is the replayed iteration's (its first run is gone).
  RollBackCounts roll_back;
  std::span<const RollBackEvent> roll_backs;
};

}  // namespace relslam::plane
