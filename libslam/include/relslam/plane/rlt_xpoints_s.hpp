#pragma once
// RltXPointsS (thesis 4.4.3.1, 4.5; spec §5.4, §5.5, §5.13): the Relative Plane algorithm's
// entry class, one call per iteration. Eigen only: no I/O, JSON or simulator; truth never
// enters.

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"
#include "relslam/plane/hints.hpp"
#include "relslam/plane/ids.hpp"
#include "relslam/plane/options.hpp"
#include "relslam/plane/rlt_map_builder.hpp"
#include "relslam/plane/rlt_plane.hpp"
#include "relslam/plane/rlt_plane_interval.hpp"
#include "relslam/plane/rlt_xmm_point.hpp"
#include "relslam/plane/rlt_xpoint.hpp"
#include "relslam/plane/rlt_xpoint_link.hpp"
#include "relslam/plane/rlt_xpoints_state.hpp"
#include "relslam/plane/roll_back.hpp"

#include <optional>
#include <span>
#include <utility>
#include <vector>

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

// RltXPointsS's per-iteration scratch, as its base like RltXPointsState (so the member names
// stay the class's own) and a value the stages can be handed: this iteration's planes in view
// and what AddPlane did with them, and ManageXPoints's working buffers. Kept from one iteration
// to the next only to avoid allocations; never restored.
struct RltXPointsScratch {
  std::vector<PlaneObject> stamped_;  // the frame's planes with their iteration set
  std::vector<PlaneId> assignment_;   // the RltPlane of each, in input order
  std::vector<char> taken_;           // per RltPlane: registered this iteration
  std::vector<PlaneMatch> matches_;
  std::vector<PlaneId> reacquired_now_;  // Rule 11 this iteration
  std::vector<RegisteredObservation> registered_;
  // ManageXPoints's.
  std::vector<int> chart_;  // Rule 22: planes in view per group
  std::vector<char> visited_;
  std::vector<XPointId> stack_;
  std::vector<PlaneId> candidates_;
  RltPlaneInterval scratch_interval_;
};

// Invariant: planes() and xpoints() are indexed by their ids; each RltPlane is in the
// unassigned list or in at least one group, or was dropped from the list (then never mapped).
// With Rules 31–34 (or rollback.force_every) the state after step() is the one a run with every
// hint now held known from the start would have (thesis 4.3.7.2: roll back, apply, roll forward).
class RltXPointsS : private RltXPointsState, private RltXPointsScratch {
 public:
  // world_T_start: the robot pose of the first frame, the map's anchor (Rule 4: "(0,0) or some
  // other inputted coordinate"). logic_error if check(options) finds a problem.
  explicit RltXPointsS(const RelativePlaneOptions& options = {}, const PlanarPose& world_T_start = {});

  // One iteration (spec §5.13): StartIteration, AddPlane for each observation, ManageXPoints,
  // ComputeXPoints (with CheckIntervalSize), BuildMap, GetPoset, then RollBack when a check asked
  // for one. Iterations must increase; planes in the robot frame.
  RelativePlaneStep step(const PlaneFrame& frame);

  // SetRollBackTo with no hint, served at the end of the next step(): the state at the end of
  // iteration target − 1 is restored and the stored inputs replayed. A testing hook (spec §8: the
  // replay must give the run that had no roll-back); refused (and counted) when the target is
  // older than the oldest state kept or neither rules.interval_check nor rollback.force_every
  // keeps any.
  void request_roll_back(int target);
  // Rule 34's general form: `hint` is added (deleting later ones) and the run rolled back to the
  // hint's iteration at the end of the next step(), as when CheckIntervalSize sends one.
  void send_hint(const RltTemporalHint& hint);
  // The plane a hint names (spec §5.11.2).
  using RltXPointsState::identity;

  const std::vector<RltPlane>& planes() const { return planes_; }
  const std::vector<RltXPoint>& xpoints() const { return xpoints_; }
  const std::vector<RltXPointLink>& links() const { return links_; }
  const std::vector<MapPlane>& map() const { return builder_.map(); }
  const std::vector<PlaneId>& unassigned() const { return unassigned_; }
  const RltPoset& pose() const { return pose_; }
  XPointId current_xpoint() const { return current_; }
  // Every motion model ever started, in order; the active one, if any, is last.
  const std::vector<RltXMMPoint>& motion_models() const { return motion_models_; }
  const RltXMMPoint* active_motion_model() const { return motion_model_active_ ? &motion_models_.back() : nullptr; }
  const RelativePlaneOptions& options() const { return options_; }
  // Rules 32/34: the hints held now.
  const RltTemporalHints& hints() const { return hints_; }
  // Every roll-back request of the run so far, in order (rollbacks.csv).
  const std::vector<RollBackEvent>& roll_back_log() const { return roll_back_log_; }
  // The stored inputs and checkpoints (empty unless roll-backs are on).
  const RltPlaneStorage& storage() const { return storage_; }

 private:
  bool keeps_history() const { return options_.rules.interval_check || options_.rollback.force_every > 0; }
  RelativePlaneStep iterate(const PlaneFrame& frame);
  void roll_back(RelativePlaneStep& result);

  void start_iteration(int iteration);
  void compute_xpoints(RelativePlaneStep& result);
  void get_poset();

  RelativePlaneOptions options_;
  PlanarPose world_T_start_;
  // Not part of the restored state (RltXPointsState): the hints are what a roll-back sends back
  // in time, the storage is where it goes back to, the log is what happened.
  RltTemporalHints hints_;
  RltPlaneStorage storage_;
  std::optional<RollBackEvent> roll_back_request_;  // the earliest target asked for this iteration
  std::vector<RollBackEvent> roll_back_log_;
  std::size_t step_log_begin_ = 0;  // this step's part of roll_back_log_

  // Per-iteration scratch, kept to avoid allocations.
  std::vector<PlaneId> failed_;  // CheckIntervalSize's planes
};

}  // namespace relslam::plane
