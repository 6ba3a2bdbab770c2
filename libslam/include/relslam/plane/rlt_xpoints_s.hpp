#pragma once
// RltXPointsS (thesis 4.4.3.1, 4.5; thesis 4.3.1, 4.3.2, 4.5): the Relative Plane algorithm's
// entry class, one call per iteration. Eigen only: no I/O, JSON or simulator; truth never
// enters.

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"
#include "relslam/plane/hints.hpp"
#include "relslam/plane/ids.hpp"
#include "relslam/plane/options.hpp"
#include "relslam/plane/relative_plane_step.hpp"
#include "relslam/plane/rlt_map_builder.hpp"
#include "relslam/plane/rlt_plane.hpp"
#include "relslam/plane/rlt_plane_interval.hpp"
#include "relslam/plane/rlt_xmm_point.hpp"
#include "relslam/plane/rlt_xpoint.hpp"
#include "relslam/plane/rlt_xpoint_link.hpp"
#include "relslam/plane/rlt_xpoints_scratch.hpp"
#include "relslam/plane/rlt_xpoints_state.hpp"
#include "relslam/plane/roll_back.hpp"

#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace relslam::plane {

// Invariant: planes() and xpoints() are indexed by their ids; each RltPlane is in the
// unassigned list or in at least one group, or was dropped from the list (then never mapped).
// With Rules 31–34 (or rollback.force_every) the state after step() is the one a run with every
// hint now held known from the start would have (thesis 4.3.7.2: roll back, apply, roll forward).
class RltXPointsS : private RltXPointsState, private RltXPointsScratch {
 public:
  // world_T_start: the robot pose of the first frame, the map's anchor (Rule 4: "(0,0) or some
  // other inputted coordinate"). logic_error if check(options) finds a problem.
  explicit RltXPointsS(const RelativePlaneOptions& options = {}, const PlanarPose& world_T_start = {});

  // One iteration (thesis 4.5): StartIteration, AddPlane for each observation, ManageXPoints,
  // ComputeXPoints (with CheckIntervalSize), BuildMap, GetPoset, then RollBack when a check asked
  // for one. Iterations must increase; planes in the robot frame.
  RelativePlaneStep step(const PlaneFrame& frame);

  // SetRollBackTo with no hint, served at the end of the next step(): the state at the end of
  // iteration target − 1 is restored and the stored inputs replayed. A testing hook (the
  // replay must give the run that had no roll-back); refused (and counted) when the target is
  // older than the oldest state kept or neither rules.interval_check nor rollback.force_every
  // keeps any.
  void request_roll_back(int target);
  // Rule 34's general form: `hint` is added (deleting later ones) and the run rolled back to the
  // hint's iteration at the end of the next step(), as when CheckIntervalSize sends one.
  void send_hint(const RltTemporalHint& hint);
  // The plane a hint names (thesis 4.3.7.2).
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
