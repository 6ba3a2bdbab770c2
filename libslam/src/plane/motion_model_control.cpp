// Motion-model control (thesis 4.3.6, Rules 23–27, walkthrough 4.5): CheckForMotionModel starts
// one after a few iterations without a pose with one mapped plane in view
// (CreateMotionModelXPoint), and a second plane on the map ends it.

#include "motion_model_control.hpp"

#include "group_charting.hpp"

#include <algorithm>
#include <optional>
#include <vector>

namespace relslam::plane {

void end_motion_model_on_the_map(RltXPointsState& s, std::span<const PlaneId> assignment, std::vector<int>& chart) {
  // thesis 4.3.6 [T/P]: the motion model ends once a second plane comes into view. Rule 29 ends
  // it when one group holds every plane in view, a new group when the second plane is new. When
  // the second plane is on the map already, in no group with the motion model's plane and at
  // Rule 21's membership cap, neither comes (Map E's fourth corner from the third loop: the
  // motion model tracked the start wall on, the pose drifting 0.05 an iteration). [C] Then the
  // chart's group — the one holding most planes in view — becomes current; the pose is GetPoset's.
  // Part of Rule 29 (a return to where the robot has been): off with it.
  const std::vector<MapPlane>& map = s.builder_.map();
  const PlaneId tracked = s.motion_models_.back().plane();
  const bool second_on_map = std::ranges::any_of(
      assignment, [&](PlaneId p) { return p != tracked && p < static_cast<PlaneId>(map.size()) && map[p].mapped; });
  if (!second_on_map) return;
  fill_chart(s, assignment, false, chart);
  const auto best = std::ranges::max_element(chart);  // the first of the most: the lowest id
  if (*best > 0) set_current(s, static_cast<XPointId>(best - chart.begin()));
}

PlaneId check_for_motion_model(RltXPointsState& s, std::span<const PlaneId> assignment,
                               const MotionModelStartOptions& options) {
  // Rule 26 (CheckForMotionModel): a few iterations without a pose within a short window.
  if (s.no_pose_count_ == 0 || s.iteration_ - s.no_pose_start_ > options.start_window) {
    s.no_pose_count_ = 0;
    s.no_pose_start_ = s.iteration_;
  }
  ++s.no_pose_count_;
  if (!options.enabled || !s.last_valid_pose_.valid) return kNone;
  if (s.no_pose_count_ < options.start_after) return kNone;
  // [R, thesis 4.3.6] exactly one plane in view, and it is on the map; blind or lost otherwise.
  if (assignment.size() != 1 || !s.builder_.map()[assignment.front()].group_placed()) return kNone;
  return assignment.front();
}

void create_motion_model(RltXPointsState& s, PlaneId plane, const PlanarPose& world_T_start,
                         const CreateMotionModelOptions& options) {
  // CreateMotionModelXPoint (Rule 27): a new group holding the one plane, linked from the
  // current group through it and fixed at the last valid pose. Entering a motion model always
  // makes a new one [T].
  const XPointId id = static_cast<XPointId>(s.xpoints_.size());
  s.planes_[plane].join(id, s.iteration_);
  s.founders_.push_back(kNone);
  RltXPoint& x = s.xpoints_.emplace_back(id, s.iteration_, std::vector<PlaneId>{plane});
  x.set_anchor(s.last_valid_pose_.world_T_robot);
  // Adaptive preset: trusted while its anchor is a checked pose (and its track, below, measures
  // its motion along the plane).
  x.set_track_trusted(s.last_valid_iteration_ == s.last_checked_iteration_);
  s.links_.push_back({s.current_, id, {plane}, false, s.iteration_});
  if (s.current_ != kNone) {
    s.xpoints_[s.current_].add_adjacent(id);
    s.xpoints_[id].add_adjacent(s.current_);
  }
  s.motion_models_.emplace_back(id, plane, s.last_valid_pose_.world_T_robot, s.last_valid_iteration_,
                                s.builder_.map()[plane].plane);
  s.motion_model_active_ = true;
  s.current_ = id;
  // Computed and placed at once, so this iteration already has its pose.
  s.motion_models_.back().compute(s.planes_, options.motion_model);
  s.xpoints_[id].set_track_trusted(s.xpoints_[id].track_trusted() && s.motion_models_.back().along_observed());
  s.xpoints_[id].compute(s.planes_, options.compute);
  s.builder_.build_map(s.links_, s.xpoints_, s.planes_, world_T_start, options.build_map);
}

}  // namespace relslam::plane
