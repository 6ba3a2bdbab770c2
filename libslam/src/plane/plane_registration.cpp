// Registration, the AddPlane part of an iteration (thesis 4.2.1, 4.2.2, walkthrough 4.5): each
// observation goes to the RltPlane it continues — Rule 1 against the previous observation of
// every recently seen RltPlane, Rule 11 against the map from a pose, Rule 10's new RltPlane for
// what nothing took.

#include "relslam/plane/rlt_xpoints_s.hpp"

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

namespace relslam::plane {

void RltXPointsS::add_planes(const PlaneFrame& frame, RelativePlaneStep& result) {
  // The frame's planes stamped with its iteration (MatchPlane's gap test and the arrays use it).
  stamped_.assign(frame.planes.begin(), frame.planes.end());
  for (PlaneObject& p : stamped_) p.iteration = frame.iteration;
  assignment_.assign(stamped_.size(), kNone);
  const RuleSwitches& rules = options_.rules;
  const std::vector<MapPlane>& map = builder_.map();

  // Rule 1: each observation against the previous observation of every recently seen RltPlane
  // (thesis 4.2.1: "the last added untransformed plane in every rltplane"), in the thesis's
  // order (4.5 AddPlane, spec §5.4.2): the RltPlanes in groups first, then the map (Rule 11),
  // and only then the unassigned list. Deviation: the thesis tries the current group and its
  // neighbours before the other groups, as a saving; every RltPlane that can pass the gap test
  // is in `recent_`, and the best score wins among them, so the outcome is the same. The
  // unassigned list must come after the map: a wall re-entering the view as a sliver at the
  // frustum's edge overlaps its mapped plane too little under a small pose error and becomes
  // a new RltPlane; were it matched before the map, every later (larger) observation would
  // follow it there and the wall would be mapped twice (Map D with noise, loop closure).
  // Deviation [C]: while the pose is lost (no pose this iteration or the last) the unassigned
  // list comes first, as the map would be searched with a pose held from long ago.
  auto match_recent = [&](bool grouped) {
    matches_.clear();
    for (int i = 0; i < static_cast<int>(stamped_.size()); ++i) {
      if (assignment_[i] != kNone) continue;
      for (PlaneId p : recent_) {
        const bool mapped = p < static_cast<PlaneId>(map.size()) && map[p].mapped;
        if (grouped != (mapped || !planes_[p].refs().empty())) continue;
        if (!rules.local_registration && mapped) continue;  // Rule 1 off: mapped planes via the pose
        const double score =
            match_plane(planes_[p].latest(), stamped_[i], options_.local_match, rules.normal_direction);
        if (score >= 0) matches_.push_back({i, p, score});
      }
    }
    register_matches(result.local_matches);
  };
  match_recent(true);

  // Rule 11: what no grouped RltPlane took is placed with a pose and matched to the map.
  bool unassigned_matched = false;
  if (rules.global_matching && last_valid_pose_.valid && std::ranges::count(assignment_, kNone) > 0) {
    const auto [world_T_robot, fresh] = pose_for_global_matching();
    if (!fresh) {
      match_recent(false);
      unassigned_matched = true;
    }
    matches_.clear();
    for (int i = 0; i < static_cast<int>(stamped_.size()); ++i)
      if (assignment_[i] == kNone)
        builder_.match_plane_to_map(i, stamped_[i], world_T_robot, options_.global_match, rules.normal_direction,
                                    taken_, matches_);
    register_matches(result.global_matches, &reacquired_now_);
  }
  if (!unassigned_matched) match_recent(false);

  // Anything left is a plane not seen before: a new RltPlane in the unassigned list.
  for (int i = 0; i < static_cast<int>(stamped_.size()); ++i)
    if (assignment_[i] == kNone) {
      assignment_[i] = create_plane(stamped_[i], i);
      ++result.new_planes;
    }
}

std::pair<PlanarPose, bool> RltXPointsS::pose_for_global_matching() {
  // The thesis places them with the previous iteration's pose (4.2.2). Deviation [C]: this
  // iteration's, from what Rule 1 registered, when that gives one — still computed from this
  // iteration's observations against the map, never carried forward. While turning the previous
  // pose lags by a whole step: 1.5° at 28 units moves a wall by 0.7, past the matching bounds,
  // and the re-seen wall would become a duplicate.
  const bool recent = last_valid_iteration_ >= iteration_ - 1;
  if (motion_model_active_) {
    RltXMMPoint& mm = motion_models_.back();
    mm.compute(planes_, options_.motion_model);
    if (const std::optional<PlanarPose> tracked = mm.world_T_robot(iteration_)) return {*tracked, true};
    return {last_valid_pose_.world_T_robot, recent};
  }
  registered_.clear();
  for (std::size_t i = 0; i < stamped_.size(); ++i)
    if (assignment_[i] != kNone) registered_.push_back({&stamped_[i], assignment_[i]});
  const RltPoset now = builder_.get_poset(registered_, planes_, options_);
  if (now.valid) return {now.world_T_robot, true};
  return {last_valid_pose_.world_T_robot, recent};
}

void RltXPointsS::register_matches(int& counter, std::vector<PlaneId>* registered) {
  // Best score first across all pairs (spec §5.4.1: at most one observation per RltPlane per
  // iteration); ties in input order, then creation order, so runs are deterministic.
  std::ranges::sort(matches_, [](const PlaneMatch& x, const PlaneMatch& y) {
    if (x.score != y.score) return x.score > y.score;
    return std::pair(x.observation, x.plane) < std::pair(y.observation, y.plane);
  });
  for (const PlaneMatch& m : matches_) {
    if (assignment_[m.observation] != kNone || taken_[m.plane]) continue;
    assignment_[m.observation] = m.plane;
    add_to_plane(m.plane, stamped_[m.observation]);
    ++counter;
    if (registered != nullptr) registered->push_back(m.plane);
  }
}

void RltXPointsS::add_to_plane(PlaneId plane, const PlaneObject& observation) {
  // AddtoTPlane: store it, and every group holding the plane has new data to compute.
  planes_[plane].add(observation);
  taken_[plane] = 1;
  for (const RltXPointRef& ref : planes_[plane].refs()) xpoints_[ref.xpoint].mark_changed();
  if (!in_recent_[plane]) {
    in_recent_[plane] = 1;
    recent_.push_back(plane);
  }
}

PlaneId RltXPointsS::create_plane(const PlaneObject& observation, int input_index) {
  const PlaneId id = static_cast<PlaneId>(planes_.size());
  planes_.emplace_back(id, observation, options_.plane_capacity);
  plane_inputs_.push_back(input_index);
  unassigned_.push_back(id);
  recent_.push_back(id);
  in_recent_.push_back(1);
  taken_.push_back(1);
  return id;
}

}  // namespace relslam::plane
