// Roll-back control (thesis 4.3.7, Rules 31–34, walkthrough 4.5): CheckIntervalSize sends hints
// (Rule 32), SetRollBackTo keeps the earliest request of an iteration, and RollBack restores a
// checkpoint and replays the stored inputs with the hints held (Rule 33: roll back, apply, roll
// forward).

#include "relslam/plane/rlt_xpoints_s.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

namespace relslam::plane {

namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

void RltXPointsS::request_roll_back(int target) {
  set_roll_back_to({.iteration_requested = iteration_, .target_iteration = target});
}

void RltXPointsS::send_hint(const RltTemporalHint& hint) {
  hints_.add(hint);
  PlaneId plane = kNone;
  for (PlaneId p = 0; p < static_cast<PlaneId>(planes_.size()) && plane == kNone; ++p)
    if (identity(p) == hint.plane) plane = p;
  set_roll_back_to({iteration_, hint.iteration, plane, hint.xpoint, static_cast<int>(hint.level)});
}

void RltXPointsS::set_roll_back_to(const RollBackEvent& request) {
  // SetRollBackTo: several requests in one iteration roll back once, to the earliest target.
  if (!roll_back_request_ || request.target_iteration < roll_back_request_->target_iteration)
    roll_back_request_ = request;
}

void RltXPointsS::check_interval_sizes(const RltXPoint& x, RelativePlaneStep& result) {
  failed_.clear();
  x.check_interval_size(planes_, options_.rollback, iteration_, failed_);
  for (PlaneId p : failed_) {
    RltXPointRef& ref = *planes_[p].ref(x.id());
    ref.hinted = true;
    const PlaneIdentity id = identity(p);
    // Rule 32: the next level for this plane. Thesis 4.5 (CheckIntervalSize): a plane that
    // started the group it fails in "should not be added to any RltXPoint" — its own new group
    // was the second try, and the replay would only make the same group again.
    const int level = founders_[x.id()] == p
                          ? static_cast<int>(HintLevel::NotOnMap)
                          : std::min(hints_.count_for(id) + 1, static_cast<int>(HintLevel::NotOnMap));
    hints_.add({static_cast<HintLevel>(level), id, ref.join_iteration, x.id()});
    ++result.roll_back.hints;
    // Rule 34: back to when the plane joined, so the hint can act there.
    set_roll_back_to({iteration_, ref.join_iteration, p, x.id(), level});
  }
}

void RltXPointsS::roll_back(RelativePlaneStep& result) {
  // RollBack (Rule 33, spec §5.11.3): restore the end of target − 1 and replay the stored inputs
  // up to now with the hints held; a roll-back asked for while replaying is served after that
  // replayed iteration (nesting), up to rollback.max_nesting in one step.
  const Clock::time_point start = Clock::now();
  const RollBackOptions& rb = options_.rollback;
  const PlaneStepTimings first_run = result.timings;
  RollBackCounts counts = result.roll_back;
  const int now = iteration_;
  int done = now;  // the state is the end of this iteration
  int restored = 0;
  std::size_t replaying = roll_back_log_.size();  // the log entry whose replay runs
  while (true) {
    if (roll_back_request_) {
      RollBackEvent event = *roll_back_request_;
      roll_back_request_.reset();
      const RltPlaneStorage::Checkpoint* from =
          restored < rb.max_nesting ? storage_.newest_at_or_before(event.target_iteration - 1) : nullptr;
      if (restored >= rb.max_nesting) {
        event.outcome = RollBackOutcome::Nesting;
      } else if (from == nullptr) {
        event.outcome = RollBackOutcome::TooOld;  // spec §5.11.3: refused, and logged
      } else {
        event.outcome = RollBackOutcome::Replayed;
        ++restored;
        storage_.drop_after(from->iteration);
        done = from->iteration;
        static_cast<RltXPointsState&>(*this) = from->state;
      }
      roll_back_log_.push_back(event);
      if (event.outcome == RollBackOutcome::Replayed) {
        ++counts.rollbacks;
        replaying = roll_back_log_.size() - 1;
      } else {
        ++counts.refused;
      }
    }
    if (done >= now) break;
    const PlaneFrame* next = storage_.frame_after(done);
    if (next == nullptr || next->iteration > now)
      throw std::logic_error("RltXPointsS::roll_back: no stored input after iteration " + std::to_string(done));
    result = iterate(*next);
    done = next->iteration;
    counts.hints += result.roll_back.hints;
    ++counts.replayed_iterations;
    ++roll_back_log_[replaying].replayed_iterations;
    storage_.checkpoint_if_due(done, *this, rb.checkpoint_period);
  }
  result.roll_back = counts;
  result.timings = first_run;
  result.timings.roll_back_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace relslam::plane
