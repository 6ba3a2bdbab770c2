// Registration, the AddPlane part of an iteration (thesis 4.2.1, 4.2.2, walkthrough 4.5): each
// observation goes to the RltPlane it continues — Rule 1 against the previous observation of
// every recently seen RltPlane, Rule 11 against the map from a pose, Rule 10's new RltPlane for
// what nothing took.

#include "plane_registration.hpp"

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

namespace relslam::plane {
namespace {

void add_to_plane(RltXPointsState& s, RltXPointsScratch& in, PlaneId plane, const PlaneObject& observation) {
  // AddtoTPlane: store it, and every group holding the plane has new data to compute.
  s.planes_[plane].add(observation);
  in.taken_[plane] = 1;
  for (const RltXPointRef& ref : s.planes_[plane].refs()) s.xpoints_[ref.xpoint].mark_changed();
  if (!s.in_recent_[plane]) {
    s.in_recent_[plane] = 1;
    s.recent_.push_back(plane);
  }
}

PlaneId create_plane(RltXPointsState& s, RltXPointsScratch& in, const PlaneObject& observation, int input_index,
                     int plane_capacity) {
  // A plane not seen before: a new RltPlane, in the unassigned list until it is grouped.
  const PlaneId id = static_cast<PlaneId>(s.planes_.size());
  s.planes_.emplace_back(id, observation, plane_capacity);
  s.plane_inputs_.push_back(input_index);
  s.unassigned_.push_back(id);
  s.recent_.push_back(id);
  s.in_recent_.push_back(1);
  in.taken_.push_back(1);
  return id;
}

void register_matches(RltXPointsState& s, RltXPointsScratch& in, int& counter,
                      std::vector<PlaneId>* registered = nullptr) {
  // Best score first across all pairs (thesis 4.3.1: at most one observation per RltPlane per
  // iteration); ties in input order, then creation order, so runs are deterministic.
  std::ranges::sort(in.matches_, [](const PlaneMatch& x, const PlaneMatch& y) {
    if (x.score != y.score) return x.score > y.score;
    return std::pair(x.observation, x.plane) < std::pair(y.observation, y.plane);
  });
  for (const PlaneMatch& m : in.matches_) {
    if (in.assignment_[m.observation] != kNone || in.taken_[m.plane]) continue;
    in.assignment_[m.observation] = m.plane;
    add_to_plane(s, in, m.plane, in.stamped_[m.observation]);
    ++counter;
    if (registered != nullptr) registered->push_back(m.plane);
  }
}

// Rule 11's pose, and whether it is of this iteration or the last (`fresh`) rather than held
// from longer ago while the pose was lost.
std::pair<PlanarPose, bool> pose_for_global_matching(RltXPointsState& s, RltXPointsScratch& in,
                                                     const RegistrationOptions& options) {
  // The thesis places them with the previous iteration's pose (4.2.2). Deviation [C]: this
  // iteration's, from what Rule 1 registered, when that gives one — still computed from this
  // iteration's observations against the map, never carried forward. While turning the previous
  // pose lags by a whole step: 1.5° at 28 units moves a wall by 0.7, past the matching bounds,
  // and the re-seen wall would become a duplicate.
  const bool recent = s.last_valid_iteration_ >= s.iteration_ - 1;
  if (s.motion_model_active_) {
    RltXMMPoint& mm = s.motion_models_.back();
    mm.compute(s.planes_, options.motion_model);
    if (const std::optional<PlanarPose> tracked = mm.world_T_robot(s.iteration_)) return {*tracked, true};
    return {s.last_valid_pose_.world_T_robot, recent};
  }
  in.registered_.clear();
  for (std::size_t i = 0; i < in.stamped_.size(); ++i)
    if (in.assignment_[i] != kNone) in.registered_.push_back({&in.stamped_[i], in.assignment_[i]});
  const RltPoset now = s.builder_.get_poset(in.registered_, s.planes_, options.get_poset);
  if (now.valid) return {now.world_T_robot, true};
  return {s.last_valid_pose_.world_T_robot, recent};
}

}  // namespace

void add_planes(RltXPointsState& s, RltXPointsScratch& in, const PlaneFrame& frame, const RegistrationOptions& options,
                RelativePlaneStep& result) {
  // The frame's planes stamped with its iteration (MatchPlane's gap test and the arrays use it).
  in.stamped_.assign(frame.planes.begin(), frame.planes.end());
  for (PlaneObject& p : in.stamped_) p.iteration = frame.iteration;
  in.assignment_.assign(in.stamped_.size(), kNone);
  const std::vector<MapPlane>& map = s.builder_.map();

  // Rule 1: each observation against the previous observation of every recently seen RltPlane
  // (thesis 4.2.1: "the last added untransformed plane in every rltplane"), in the thesis's
  // order (4.5 AddPlane, thesis 4.3.1): the RltPlanes in groups first, then the map (Rule 11),
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
    in.matches_.clear();
    for (int i = 0; i < static_cast<int>(in.stamped_.size()); ++i) {
      if (in.assignment_[i] != kNone) continue;
      for (PlaneId p : s.recent_) {
        const bool mapped = p < static_cast<PlaneId>(map.size()) && map[p].mapped;
        if (grouped != (mapped || !s.planes_[p].refs().empty())) continue;
        if (!options.local_registration && mapped) continue;  // Rule 1 off: mapped planes via the pose
        const double score =
            match_plane(s.planes_[p].latest(), in.stamped_[i], options.local_match, options.normal_direction);
        if (score >= 0) in.matches_.push_back({i, p, score});
      }
    }
    register_matches(s, in, result.local_matches);
  };
  match_recent(true);

  // Rule 11: what no grouped RltPlane took is placed with a pose and matched to the map.
  bool unassigned_matched = false;
  if (options.global_matching && s.last_valid_pose_.valid && std::ranges::count(in.assignment_, kNone) > 0) {
    const auto [world_T_robot, fresh] = pose_for_global_matching(s, in, options);
    if (!fresh) {
      match_recent(false);
      unassigned_matched = true;
    }
    in.matches_.clear();
    for (int i = 0; i < static_cast<int>(in.stamped_.size()); ++i)
      if (in.assignment_[i] == kNone)
        s.builder_.match_plane_to_map(i, in.stamped_[i], world_T_robot, options.global_match, options.normal_direction,
                                      in.taken_, in.matches_);
    register_matches(s, in, result.global_matches, &in.reacquired_now_);
  }
  if (!unassigned_matched) match_recent(false);

  // Anything left is a plane not seen before: a new RltPlane in the unassigned list.
  for (int i = 0; i < static_cast<int>(in.stamped_.size()); ++i)
    if (in.assignment_[i] == kNone) {
      in.assignment_[i] = create_plane(s, in, in.stamped_[i], i, options.plane_capacity);
      ++result.new_planes;
    }
}

}  // namespace relslam::plane
