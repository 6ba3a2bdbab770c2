// Roll-back control (thesis 4.3.7, Rules 31–34, walkthrough 4.5): CheckIntervalSize sends hints
// (Rule 32), SetRollBackTo keeps the earliest request of an iteration, and RollBack restores a
// checkpoint and replays the stored inputs with the hints held (Rule 33: roll back, apply, roll
// forward).

#include "relslam/plane/rlt_xpoints_s.hpp"

#include "roll_back_control.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

namespace relslam::plane {
namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

void RltXPointsS::request_roll_back(int target) {
  set_roll_back_to(roll_back_request_, {.iteration_requested = iteration_, .target_iteration = target});
}

void RltXPointsS::send_hint(const RltTemporalHint& hint) {
  hints_.add(hint);
  PlaneId plane = kNone;
  for (PlaneId p = 0; p < static_cast<PlaneId>(planes_.size()) && plane == kNone; ++p)
    if (identity(p) == hint.plane) plane = p;
  set_roll_back_to(roll_back_request_, {iteration_, hint.iteration, plane, hint.xpoint, static_cast<int>(hint.level)});
}

void set_roll_back_to(std::optional<RollBackEvent>& pending, const RollBackEvent& request) {
  // SetRollBackTo: several requests in one iteration roll back once, to the earliest target.
  if (!pending || request.target_iteration < pending->target_iteration) pending = request;
}

int check_interval_sizes(RltXPointsState& s, const RltXPoint& x, const RollBackOptions& options,
                         RltTemporalHints& hints, std::vector<PlaneId>& failed, std::optional<RollBackEvent>& pending) {
  int sent = 0;
  failed.clear();
  x.check_interval_size(s.planes_, options, s.iteration_, failed);
  for (PlaneId p : failed) {
    RltXPointRef& ref = *s.planes_[p].ref(x.id());
    ref.hinted = true;
    const PlaneIdentity id = s.identity(p);
    // Rule 32: the next level for this plane. Thesis 4.5 (CheckIntervalSize): a plane that
    // started the group it fails in "should not be added to any RltXPoint" — its own new group
    // was the second try, and the replay would only make the same group again.
    const int level = s.founders_[x.id()] == p
                          ? static_cast<int>(HintLevel::NotOnMap)
                          : std::min(hints.count_for(id) + 1, static_cast<int>(HintLevel::NotOnMap));
    hints.add({static_cast<HintLevel>(level), id, ref.join_iteration, x.id()});
    ++sent;
    // Rule 34: back to when the plane joined, so the hint can act there.
    set_roll_back_to(pending, {s.iteration_, ref.join_iteration, p, x.id(), level});
  }
  return sent;
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
