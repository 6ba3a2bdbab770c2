// The Relative Plane iteration's sequencer (thesis 4.4.3.1, walkthrough 4.5): StartIteration,
// AddPlane, ManageXPoints, ComputeXPoints, BuildMap, GetPoset and RollBack, in that order. The
// stages live in their own files: plane_registration.cpp (Rules 1, 10, 11), group_management.cpp
// (Rules 7–9, 12, 21), group_charting.cpp (Rules 22, 29, 37), motion_model_control.cpp (Rules
// 23–27) and roll_back_control.cpp (Rules 31–34). The first four are free functions or a small
// class on RltXPointsState and the per-iteration RltXPointsScratch, each taking the narrowest
// options view it needs; roll-back control stays with the class, as it restores the whole state
// and replays iterate().

#include "relslam/plane/rlt_xpoints_s.hpp"

#include "relslam/core/checked_options.hpp"

#include "group_management.hpp"
#include "line_placement_control.hpp"
#include "motion_model_control.hpp"
#include "plane_registration.hpp"
#include "pose_check_control.hpp"
#include "roll_back_control.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <utility>

namespace relslam::plane {
namespace {

using Clock = std::chrono::steady_clock;

// Milliseconds since `start`, which moves on to now.
double lap(Clock::time_point& start) {
  const Clock::time_point now = Clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - start).count();
  start = now;
  return ms;
}

}  // namespace

RltXPointsS::RltXPointsS(const RelativePlaneOptions& options, const PlanarPose& world_T_start)
    : options_(checked_options(options, "RltXPointsS")), world_T_start_(world_T_start) {
  options_.motion_model.real_end_motion = cut_ends_open(options);
  options_.motion_model.track_along = cut_ends_open(options) || map_grounded(options);
}

RelativePlaneStep RltXPointsS::step(const PlaneFrame& frame) {
  if (started_ && frame.iteration <= iteration_)
    throw std::logic_error("RltXPointsS::step: iteration " + std::to_string(frame.iteration) + " after " +
                           std::to_string(iteration_));
  const RollBackOptions& rb = options_.rollback;
  step_log_begin_ = roll_back_log_.size();
  if (keeps_history()) {
    // PlaneRecord (thesis 4.4.3.17): the input is kept for the replay; before the first one the
    // empty state is kept, so a roll-back can reach the start of the run.
    if (storage_.oldest() == nullptr) storage_.checkpoint_if_due(frame.iteration - 1, *this, rb.checkpoint_period);
    storage_.record(frame);
  }
  RelativePlaneStep result = iterate(frame);
  if (rb.force_every > 0 && frame.iteration > 0 && frame.iteration % rb.force_every == 0)
    set_roll_back_to(roll_back_request_,
                     {.iteration_requested = frame.iteration, .target_iteration = frame.iteration - rb.force_depth});
  // Walkthrough 4.5: RollBack is called last, after GetPoset.
  if (roll_back_request_) roll_back(result);
  if (keeps_history()) {
    storage_.checkpoint_if_due(iteration_, *this, rb.checkpoint_period);
    storage_.trim(iteration_, rb.max_depth);
  }

  const RltPoset& reported = options_.preset == Preset::Adaptive ? checked_pose_ : pose_;
  result.world_T_robot = reported.world_T_robot;
  result.pose_valid = reported.valid;
  result.pose_planes = reported.planes_used;
  result.pose_reason = reported.reason;
  result.assignment = assignment_;
  result.map = builder_.map();
  result.groups = xpoints_;
  result.links = links_;
  result.current_group = current_;
  result.motion_model = active_motion_model();
  result.roll_backs = std::span<const RollBackEvent>(roll_back_log_).subspan(step_log_begin_);
  return result;
}

RelativePlaneStep RltXPointsS::iterate(const PlaneFrame& frame) {
  RelativePlaneStep result;
  result.iteration = frame.iteration;
  Clock::time_point t = Clock::now();
  start_iteration(frame.iteration);
  add_planes(*this, *this, frame, RegistrationOptions::of(options_), result);
  result.timings.add_ms = lap(t);
  GroupManagement(*this, *this, hints_, GroupingOptions::of(options_)).manage_xpoints(result);
  result.timings.manage_ms = lap(t);
  compute_xpoints(result);
  result.timings.compute_ms = lap(t);
  const BuildMapOptions build_options(options_);
  builder_.build_map(links_, xpoints_, planes_, world_T_start_, build_options, line_map_);
  result.timings.build_ms = lap(t);
  get_poset();
  result.timings.pose_ms = lap(t);
  return result;
}

void RltXPointsS::start_iteration(int iteration) {
  iteration_ = iteration;
  started_ = true;
  // Only RltPlanes seen within the iteration gap can pass MatchPlane's last test, so Rule 1
  // needs to look at no others (thesis 4.3.8: registration linear in the planes seen).
  const int gap = options_.local_match.max_iteration_gap;
  std::erase_if(recent_, [&](PlaneId p) {
    const bool stale = gap >= 0 && iteration - planes_[p].last_iteration() > gap;
    if (stale) in_recent_[p] = 0;
    return stale;
  });
  taken_.assign(planes_.size(), 0);
  reacquired_now_.clear();
}

void RltXPointsS::compute_xpoints(RelativePlaneStep& result) {
  const bool reorder = options_.key_points && (options_.rules.reorder_planes || options_.rules.reorder_broken_chains ||
                                               chains_through_consistent_ends(options_));
  const ComputeXPointOptions compute_options(options_);
  const ReorderPlanesOptions reorder_options(options_);
  for (RltXPoint& x : xpoints_)
    if (x.needs_compute() && !x.motion_model()) {
      if (reorder) x.reorder_if_due(planes_, reorder_options, iteration_);  // Rule 30 (thesis 4.4.3.2)
      x.compute(planes_, compute_options);
      if (options_.rules.interval_check)  // Rules 31, 32 (walkthrough 4.5)
        result.roll_back.hints +=
            check_interval_sizes(*this, x, options_.rollback, hints_, failed_, roll_back_request_);
      ++result.groups_computed;
    }
  // A motion model re-runs its track over its plane's observations (thesis 4.3.6).
  for (RltXMMPoint& mm : motion_models_) {
    RltXPoint& x = xpoints_[mm.xpoint()];
    if (!x.needs_compute()) continue;
    if (!mm.ended()) mm.compute(planes_, options_.motion_model);  // an ended track is frozen
    x.set_track_trusted(x.track_trusted() && mm.along_observed());
    x.compute(planes_, compute_options);                          // only clears the flag
    ++result.groups_computed;
  }
}

void RltXPointsS::get_poset() {
  registered_.clear();
  for (std::size_t i = 0; i < stamped_.size(); ++i) registered_.push_back({&stamped_[i], assignment_[i]});
  pose_ = builder_.get_poset(registered_, planes_, options_);
  if (!pose_.valid && !motion_model_active_) {
    const PlaneId plane = check_for_motion_model(*this, assignment_, MotionModelStartOptions::of(options_));
    if (plane != kNone) create_motion_model(*this, plane, world_T_start_, CreateMotionModelOptions::of(options_));
  }
  // While a motion model is active its track is the pose (thesis 4.3.6), also for Rule 11.
  if (motion_model_active_) {
    const std::optional<PlanarPose> tracked = motion_models_.back().world_T_robot(iteration_);
    pose_ = {tracked.value_or(PlanarPose{}), tracked.has_value(), tracked ? 1 : 0};
  }
  if (options_.preset == Preset::Adaptive) check_poset(*this, *this, options_.integrity);
  if (lines_placed(options_)) {
    const bool held = hold_along(*this, *this, options_.integrity, world_T_start_);
    gather_line_evidence(*this, *this, BuildMapOptions(options_).line, held);
  }
  if (pose_.valid) {
    last_valid_pose_ = pose_;
    last_valid_iteration_ = iteration_;
    no_pose_count_ = 0;
  }
}

// Roll-back requests and RollBack (Rule 33, thesis 4.3.7.2: roll back, apply, roll forward).

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

void RltXPointsS::roll_back(RelativePlaneStep& result) {
  // RollBack (Rule 33, thesis 4.3.7.2): restore the end of target − 1 and replay the stored inputs
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
        event.outcome = RollBackOutcome::TooOld;  // thesis 4.3.7.2: refused, and logged
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
