#pragma once
// Going back in time (Rules 33, 34; thesis 4.2.6, 4.3.7.2, 4.4.3.17, walkthrough 4.5 RollBack;
// thesis 4.3.7.2): the stored input of every recent iteration (the PlaneRecords of
// RltPlaneStorage) and copies of the algorithm's whole state, from which RltXPointsS restores the
// end of the iteration before a roll-back's target and replays the stored inputs. Eigen only.

#include "relslam/core/plane_object.hpp"
#include "relslam/plane/hints.hpp"
#include "relslam/plane/ids.hpp"
#include "relslam/plane/rlt_xpoints_state.hpp"

#include <cstddef>
#include <deque>
#include <string_view>

namespace relslam::plane {

// What became of a roll-back request.
enum class RollBackOutcome : unsigned char {
  Replayed,  // restored and replayed to the current iteration (or until a nested roll-back)
  TooOld,    // its target is older than the oldest state kept (rollback.max_depth): refused
  Nesting,   // one step already rolled back rollback.max_nesting times: refused
};
std::string_view to_string(RollBackOutcome outcome);  // "replayed", "too_old", "nesting"

// One roll-back (rollbacks.csv). A forced one (a test, rollback.force_every) has no plane.
struct RollBackEvent {
  int iteration_requested = 0;  // the iteration (maybe a replayed one) whose check asked for it
  int target_iteration = 0;     // restored to the end of the iteration before this one
  PlaneId plane = kNone;        // the plane whose hint set it off, its group and the hint's level
  XPointId xpoint = kNone;
  int level = 0;                // HintLevel, 0: none (forced)
  int replayed_iterations = 0;  // replayed before the current iteration or the next roll-back
  RollBackOutcome outcome = RollBackOutcome::Replayed;
};

// RltPlaneStorage (thesis 4.4.3.17): the inputs of the recent iterations and checkpoints of the
// state. Deviation (a literal reading cuts every buffer back by hand; the thesis notes that
// rolling back is quick and the replay is what costs): a checkpoint is a copy of the whole state,
// kept every rollback.checkpoint_period iterations, so nothing can be left out of the restore;
// the replay starts at the checkpoint, at most one period before the target.
// Invariant: frames and checkpoints are in increasing iteration order, and every frame after the
// oldest checkpoint is kept; each checkpoint is the state its iteration ended with under the
// hints now held (a roll-back drops those after its target, and the replay makes them again).
class RltPlaneStorage {
 public:
  struct Checkpoint {
    int iteration = 0;  // the state at the end of this iteration
    RltXPointsState state;
  };

  // The input of one iteration, in iteration order (PlaneRecord).
  void record(const PlaneFrame& frame);
  // Keeps `state` as the end of `iteration` when the newest checkpoint is `period` or more
  // iterations older (or there is none).
  void checkpoint_if_due(int iteration, const RltXPointsState& state, int period);
  // The newest checkpoint at or before `iteration`; nullptr when all are later (too old).
  const Checkpoint* newest_at_or_before(int iteration) const;
  // Drops the checkpoints after `iteration`: they were made under hints a roll-back changed.
  void drop_after(int iteration);
  // The first recorded frame after `iteration`; nullptr when none.
  const PlaneFrame* frame_after(int iteration) const;
  // Keeps only what a roll-back to `now` − max_depth needs: the newest checkpoint at or before
  // that iteration, those after it and the frames after the oldest kept (memory stays bounded).
  void trim(int now, int max_depth);

  std::size_t checkpoints() const { return checkpoints_.size(); }
  std::size_t frames() const { return frames_.size(); }
  // Iteration of the oldest checkpoint (none: no roll-back can be served).
  const Checkpoint* oldest() const { return checkpoints_.empty() ? nullptr : &checkpoints_.front(); }

 private:
  std::deque<PlaneFrame> frames_;
  std::deque<Checkpoint> checkpoints_;
};

}  // namespace relslam::plane
