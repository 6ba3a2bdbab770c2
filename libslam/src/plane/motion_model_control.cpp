// Motion-model control (thesis 4.3.6, Rules 23–27, walkthrough 4.5): CheckForMotionModel starts
// one after a few iterations without a pose with one mapped plane in view
// (CreateMotionModelXPoint), and a second plane on the map ends it.

#include "relslam/plane/rlt_xpoints_s.hpp"

#include "group_charting.hpp"

#include <algorithm>
#include <optional>
#include <vector>

namespace relslam::plane {

void RltXPointsS::end_motion_model_on_the_map() {
  // Spec §5.10.4 [T/P]: the motion model ends once a second plane comes into view. Rule 29 ends
  // it when one group holds every plane in view, a new group when the second plane is new. When
  // the second plane is on the map already, in no group with the motion model's plane and at
  // Rule 21's membership cap, neither comes (Map E's fourth corner from the third loop: the
  // motion model tracked the start wall on, the pose drifting 0.05 an iteration). [C] Then the
  // chart's group — the one holding most planes in view — becomes current; the pose is GetPoset's.
  // Part of Rule 29 (a return to where the robot has been): off with it.
  const std::vector<MapPlane>& map = builder_.map();
  const PlaneId tracked = motion_models_.back().plane();
  const bool second_on_map = std::ranges::any_of(
      assignment_, [&](PlaneId p) { return p != tracked && p < static_cast<PlaneId>(map.size()) && map[p].mapped; });
  if (!second_on_map) return;
  fill_chart(*this, assignment_, false, chart_);
  const auto best = std::ranges::max_element(chart_);  // the first of the most: the lowest id
  if (*best > 0) set_current(*this, static_cast<XPointId>(best - chart_.begin()));
}

void RltXPointsS::check_for_motion_model() {
  // Rule 26 (CheckForMotionModel): a few iterations without a pose within a short window.
  if (no_pose_count_ == 0 || iteration_ - no_pose_start_ > options_.motion_model.start_window) {
    no_pose_count_ = 0;
    no_pose_start_ = iteration_;
  }
  ++no_pose_count_;
  if (!options_.key_points || !options_.rules.motion_model || !last_valid_pose_.valid) return;
  if (no_pose_count_ < options_.motion_model.start_after) return;
  // [R, spec §5.10.2] exactly one plane in view, and it is on the map; blind or lost otherwise.
  if (assignment_.size() != 1 || !builder_.map()[assignment_.front()].mapped) return;
  create_motion_model(assignment_.front());
}

void RltXPointsS::create_motion_model(PlaneId plane) {
  // CreateMotionModelXPoint (Rule 27): a new group holding the one plane, linked from the
  // current group through it and fixed at the last valid pose. Entering a motion model always
  // makes a new one [T].
  const XPointId id = static_cast<XPointId>(xpoints_.size());
  planes_[plane].join(id, iteration_);
  founders_.push_back(kNone);
  RltXPoint& x = xpoints_.emplace_back(id, iteration_, std::vector<PlaneId>{plane});
  x.set_anchor(last_valid_pose_.world_T_robot);
  links_.push_back({current_, id, {plane}, false, iteration_});
  if (current_ != kNone) {
    xpoints_[current_].add_adjacent(id);
    xpoints_[id].add_adjacent(current_);
  }
  motion_models_.emplace_back(id, plane, last_valid_pose_.world_T_robot, last_valid_iteration_,
                              builder_.map()[plane].plane);
  motion_model_active_ = true;
  current_ = id;
  // Computed and placed at once, so this iteration already has its pose.
  motion_models_.back().compute(planes_, options_.motion_model);
  xpoints_[id].compute(planes_, options_);
  builder_.build_map(links_, xpoints_, planes_, world_T_start_, options_);
}

}  // namespace relslam::plane
