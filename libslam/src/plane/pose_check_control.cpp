// The adaptive preset's pose check (beyond the thesis; pose_integrity.hpp): a pose is valid
// when the planes it rests on fix it and agree with the map, or when the motion model carries
// it (its stated case: one plane in view) and the planes in view agree with its track; when lost
// for integrity.recover_after iterations, the planes in view are matched against the whole map.

#include "pose_check_control.hpp"

#include "relslam/plane/end_fix.hpp"

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

namespace relslam::plane {
namespace {

// The motion model's track (GetPoset's pose while one is active) as the pose, when every mapped
// plane in view agrees with it.
IntegrityResult motion_model_pose(const RltXPointsState& s, std::span<const LinePair> pairs,
                                  const IntegrityOptions& options) {
  IntegrityResult out;
  out.reason = PoseReason::Disagree;
  // Only a track that starts from a checked pose: one anchored on a pose the check refused
  // (parallel planes, a sliding piece taken as static) carries that pose's error along.
  if (!s.pose_.valid || s.motion_models_.back().start_iteration() != s.last_checked_iteration_) return out;
  // Nor one that dropped the motion along its plane unmeasured (Rule 25, RltXMMPoint::along_observed).
  if (!s.motion_models_.back().along_observed()) return out;
  if (!std::ranges::all_of(pairs, [&](const LinePair& p) { return agrees(p, s.pose_.world_T_robot, options); }))
    return out;
  return {s.pose_.world_T_robot, true, PoseReason::MotionModel, 1};
}

std::optional<IntegrityResult> recovered_pose(const RltXPointsState& s, const RltXPointsScratch& in,
                                              const IntegrityOptions& options) {
  // Only within the robot's reach of the last checked pose (max_step per iteration since): along
  // a corridor of equal pieces a wider search finds the wrong piece as readily as the right one.
  // The reach grows for as long as the pose is lost, so the robot's true place stays inside it
  // and competes with any place that fits by chance (a reach held at continuity_window
  // iterations left only wrong places to find after a long loss on the generated offices).
  if (!s.last_checked_pose_.valid) return std::nullopt;
  std::vector<PlaneObject> map;
  std::vector<int> index_of(s.builder_.map().size(), -1);  // PlaneId -> index in `map`
  for (std::size_t p = 0; p < s.builder_.map().size(); ++p)
    if (s.builder_.map()[p].mapped) {
      index_of[p] = static_cast<int>(map.size());
      map.push_back(s.builder_.map()[p].plane);
    }
  // A plane in view that Rule 1 registered to a mapped RltPlane keeps that map plane.
  std::vector<int> known;
  for (const PlaneId p : in.assignment_)
    known.push_back(p != kNone && p < static_cast<PlaneId>(index_of.size()) ? index_of[p] : -1);
  const int gap = s.iteration_ - s.last_checked_iteration_;
  return relocalize(in.stamped_, map, NearPose{s.last_checked_pose_.world_T_robot, options.max_step * gap + options.offset_bound},
                    options, known);
}

// A relocalised pose is valid only when the find before it, at most recover_after iterations
// earlier, lies within the robot's reach of it [C]: a place that fits the planes in view by
// chance (a map the robot has not yet seen the right part of) seldom fits again a step later.
bool confirmed(RltXPointsState& s, const IntegrityResult& found, const IntegrityOptions& options) {
  const int gap = s.iteration_ - s.recovery_candidate_iteration_;
  const bool confirms = s.recovery_candidate_.valid && gap <= options.recover_after &&
                        within_reach(found.world_T_robot, s.recovery_candidate_.world_T_robot, gap, options);
  s.recovery_candidate_ = {found.world_T_robot, true, found.planes, found.reason};
  s.recovery_candidate_iteration_ = s.iteration_;
  return confirms;
}

// The mapped planes, world frame, as relocalisation and the view evidence read them.
std::vector<PlaneObject> mapped_planes(const RltXPointsState& s) {
  std::vector<PlaneObject> map;
  for (const MapPlane& m : s.builder_.map())
    if (m.mapped) map.push_back(m.plane);
  return map;
}

// The pose from mapped planes in one direction and their real ends (end_fix.hpp): a map plane's
// end is real when the plane was seen keeping its size or is anchored on that end (Rule 17),
// and the place must pass the view evidence as a relocalised one does.
IntegrityResult ends_pose(const RltXPointsState& s, const RltXPointsScratch& in, const IntegrityOptions& options,
                          const std::optional<std::pair<PlanarPose, int>>& previous) {
  std::vector<EndPair> pairs;
  const std::vector<MapPlane>& map = s.builder_.map();
  for (std::size_t i = 0; i < in.stamped_.size(); ++i) {
    const PlaneId p = in.assignment_[i];
    if (p == kNone || p >= static_cast<PlaneId>(map.size()) || !map[p].mapped || !map[p].grounded) continue;
    const MapPlane& m = map[p];
    pairs.push_back({{in.stamped_[i], m.plane},
                     m.size_static || m.key_point == KeyPoint::Left,
                     m.size_static || m.key_point == KeyPoint::Right});
  }
  IntegrityResult r = fit_pose_to_ends(pairs, options, previous);
  if (r.valid && contradicted(r.world_T_robot, in.stamped_, mapped_planes(s), options))
    r = {r.world_T_robot, false, PoseReason::Disagree, r.planes};
  return r;
}

}  // namespace

std::vector<LinePair> line_pairs(const RltXPointsState& s, const RltXPointsScratch& in) {
  std::vector<LinePair> pairs;
  const std::vector<MapPlane>& map = s.builder_.map();
  for (std::size_t i = 0; i < in.stamped_.size(); ++i) {
    const PlaneId p = in.assignment_[i];
    // Only planes placed without a motion model's guess (MapPlane::grounded) can check a pose.
    if (p != kNone && p < static_cast<PlaneId>(map.size()) && map[p].mapped && map[p].grounded)
      pairs.push_back({in.stamped_[i], map[p].plane});
  }
  return pairs;
}

void check_poset(RltXPointsState& s, const RltXPointsScratch& in, const IntegrityOptions& options) {
  std::optional<std::pair<PlanarPose, int>> previous;
  if (s.last_checked_pose_.valid)
    previous.emplace(s.last_checked_pose_.world_T_robot, s.iteration_ - s.last_checked_iteration_);
  const std::vector<LinePair> pairs = line_pairs(s, in);
  IntegrityResult r = check_pose(pairs, options, previous);
  // The motion model's stated case (Rules 23-27): its track while the lines fix no pose.
  const bool unfixed = r.reason == PoseReason::NoPlanes || r.reason == PoseReason::OneDirection;
  // Parallel planes with real ends in view: measured along the walls, before the motion model's guess.
  if (r.reason == PoseReason::OneDirection && options.real_ends && options.field_of_view.known)
    if (const IntegrityResult e = ends_pose(s, in, options, previous); e.valid) r = e;
  if (!r.valid && unfixed && s.motion_model_active_) r = motion_model_pose(s, pairs, options);
  if (!r.valid && options.recovery && s.iteration_ - s.last_checked_iteration_ >= options.recover_after)
    if (const std::optional<IntegrityResult> found = recovered_pose(s, in, options))
      if (confirmed(s, *found, options)) r = *found;
  s.checked_pose_ = {r.world_T_robot, r.valid, r.planes, r.reason};
  // The last pose the lines fixed (a motion model's track is not one): continuity, recovery's
  // reach and the motion model's anchor are judged from it.
  if (!r.valid || r.reason == PoseReason::MotionModel) return;
  s.last_checked_pose_ = s.checked_pose_;
  s.last_checked_iteration_ = s.iteration_;
  // A checked pose is the better one for Rule 11 and a motion model's anchor (Rule 27).
  s.pose_ = s.checked_pose_;
  s.last_valid_pose_ = s.pose_;
  s.last_valid_iteration_ = s.iteration_;
  s.no_pose_count_ = 0;
  // A relocalised place becomes the pose the algorithm runs on (Rule 11 places the planes in view
  // from it), but is reported valid only once the lines or real ends confirm it, within the
  // robot's reach of it [C]: in a generated mirrored corridor a place turned by 180 degrees fit
  // the planes in view again every few iterations while no plane in view ever came onto the map
  // there (docs/generated-maps.md).
  if (r.reason == PoseReason::Recovered) s.checked_pose_.valid = false;
}

}  // namespace relslam::plane
