#include "relslam/point/rlt_mapper.hpp"

#include "relslam/core/checked_options.hpp"
#include "relslam/point/rlt_icp.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace relslam::point {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point& t) {
  const auto now = Clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - t).count();
  t = now;
  return ms;
}

// Rejected registrations in a row after which the predicted rotation is taken for stale [C]:
// a mismatch rejected by max_turn_deg alternated with correct registrations (density 5, seed 1),
// while a prediction drifted off in a long stretch without registered rotation is rejected in
// every iteration.
constexpr int kMaxRejectedTurns = 10;

}  // namespace

RltMapper::RltMapper(const PointSlamOptions& options, GroupRelaxer relaxer)
    : options_(checked_options(options, "RltMapper")),
      map_(options_),
      matcher_(options_),
      turn_rate_(turn_rate_window_on(options_)),
      relaxer_(std::move(relaxer)) {
  if (options_.global_relaxation != GlobalRelaxation::Off && !relaxer_)
    throw std::logic_error("RltMapper: global_relaxation " + std::string(to_string(options_.global_relaxation)) +
                           " needs a GroupRelaxer");
}

RltMapper::RltMapper(RltMapper&&) noexcept = default;
RltMapper::~RltMapper() = default;

StepResult RltMapper::step(const ObservationFrame& frame) { return step(frame, {}); }

StepResult RltMapper::step(const ObservationFrame& frame, const std::vector<std::pair<int, PointId>>& forced_matches) {
  const int k = frame.iteration;
  if (map_.iteration != kNone && k <= map_.iteration)
    throw std::logic_error("RltMapper::step: iteration " + std::to_string(k) + " after " +
                           std::to_string(map_.iteration));
  for (const Eigen::Vector3d& p : frame.points)
    if (!p.allFinite())
      throw std::logic_error("RltMapper::step: non-finite observation at iteration " + std::to_string(k));
  if (map_.first_iteration == kNone) map_.first_iteration = k;
  map_.iteration = k;

  StepResult result;
  result.iteration = k;
  auto clock = Clock::now();

  // [init] Local candidates: latest observations of points seen in the last few iterations;
  // a non-incremental global index reloads the whole map here (Fig 110).
  map_.charting.begin_iteration(k);
  build_local_index(k, frame.odometry);
  map_.global_index->prepare();
  result.timings.init_ms = ms_since(clock);

  // [load] Local, then global matching, then new RltPoints (thesis 6.2.5).
  const bool loop_closed = load(frame, forced_matches, result);
  result.timings.load_ms = ms_since(clock);

  // [merge] New points that turned out to be old ones (thesis 6.5.2).
  if (options_.merge_points) result.merges = merging_.merge_due(map_, k, options_.merge_bound);
  result.timings.merge_ms = ms_since(clock);

  // [compute] Groups with a new observation, oldest first so anchors are fresh (thesis 6.3.3).
  compute_groups(k);
  result.timings.compute_ms = ms_since(clock);

  // [creation] Temporary, then final groups (thesis 6.4.3), then clean-up (6.5.5).
  const CreationReport created = creation_.create_groups(map_, k, options_);
  result.groups_created = created.groups_created;
  result.dynamic_flagged = created.dynamic_flagged;
  result.binning_comparisons = created.binning_comparisons;
  result.timings.binning_ms = created.binning_ms;
  check_map_frame(k);
  if (k % options_.temporary_cleanup_period == 0) creation_.retire_redundant_temporary_groups(map_, k, options_);
  result.timings.create_ms = ms_since(clock);

  // [relax] Beyond the thesis: all group-to-world transforms at once. A loop closure
  // schedules the solve once the groups tying the re-found points to the new ones exist (the
  // final level's look-ahead later); further closures wait for it.
  schedule_relaxation(k, loop_closed, result);
  result.timings.relax_ms = ms_since(clock);

  // [pose] Current position (thesis 6.1): used for the next global matching and for metrics.
  update_pose(frame, result);
  result.timings.pose_ms = ms_since(clock);
  result.changed = map_.take_changed();
  return result;
}

void RltMapper::build_local_index(int k, const std::optional<Rigid3>& odometry) {
  scratch_ids_.clear();
  map_.charting.enumerate_unique(k - options_.match_look_back, k - 1, scratch_ids_);
  local_candidates_.clear();
  // Dynamic points stay locally matchable, so a mover does not start a new RltPoint every frame
  // (thesis 6.2.5).
  for (PointId id : scratch_ids_) {
    const RltPoint& p = map_.points[id];
    if (!p.merged) local_candidates_.push_back(local_candidate(p, k));
  }
  matcher_.prepare(local_candidates_, k, options_.use_odometry ? odometry : std::nullopt);
}

LocalCandidate RltMapper::local_candidate(const RltPoint& p, int k) const {
  // The latest observation, wherever in the window it was (thesis 6.2.3).
  const Point& latest = p.observations.latest();
  const LocalCandidate observed{p.id, latest.p, latest.iteration};
  // Deviation (adaptive preset): a point on the map seen in the previous iteration is
  // expected where the map puts it in that iteration's robot frame. Its latest observation
  // carries a whole observation's noise, and once two close landmarks swapped (sigma >= 0.2,
  // landmarks 0.7-2 apart) each point follows the other's observations from then on: the map
  // ended with two points for one landmark and none for the other. The map's place averages
  // many observations, so a swap stays one wrong observation. Only where the previous pose
  // rests on the map and the map agrees with the latest observation within the noise-only
  // bound (it may not, for a point just found again after a long loop).
  if (options_.preset != Preset::Adaptive || !pose_from_map_ || !p.on_map() || latest.iteration != k - 1)
    return observed;
  const Eigen::Vector3d expected = pose_.inverse_apply(p.global);
  if ((expected - latest.p).norm() > options_.compensated_bound) return observed;
  return {p.id, expected, latest.iteration};
}

PointId RltMapper::create_point(const Eigen::Vector3d& p, int k) {
  const auto id = static_cast<PointId>(map_.points.size());
  map_.points.emplace_back(options_.ring_capacity);
  RltPoint& point = map_.points.back();
  point.id = id;
  point.creation_iteration = k;
  point.first_observation = {p, k};
  record(id, p, k, true);
  creation_.add_point(id, options_);
  if (options_.merge_points) merging_.schedule(id, k + options_.merge_delay);
  return id;
}

void RltMapper::record(PointId id, const Eigen::Vector3d& p, int k, bool returned) {
  RltPoint& point = map_.points[id];
  point.observations.push({p, k});
  point.interval.add(k);
  map_.charting.add(id);
  // A point starting a visible run while still ungrouped at a level waits in that level's list,
  // its run's start standing in for the creation iteration. New points always enter both.
  if (returned && !point.dynamic)
    for (GroupLevel level : {GroupLevel::Temporary, GroupLevel::Final}) wait_for_group(map_, id, level, k, options_);
  // Notify its groups (thesis 6.3.3): each is computed once this iteration.
  if (group_queued_at_.size() < map_.groups.size()) group_queued_at_.resize(map_.groups.size(), kNone);
  for (const RltGroupRef& ref : point.groups) {
    if (!map_.groups[ref.group].alive() || group_queued_at_[ref.group] == k) continue;
    group_queued_at_[ref.group] = k;
    queued_groups_.push_back(ref.group);
  }
}

bool RltMapper::load(const ObservationFrame& frame, const std::vector<std::pair<int, PointId>>& forced_matches,
                     StepResult& result) {
  const int k = frame.iteration;
  const MatchResult& match = matcher_.match(frame.points, k, *map_.global_index, map_.points, pose_);
  result.assignment = match.assigned;
  result.local_matches = match.local;
  result.global_matches = match.global;
  for (const auto& [observation, id] : forced_matches) {
    if (observation < 0 || static_cast<std::size_t>(observation) >= result.assignment.size() || id < 0 ||
        static_cast<std::size_t>(id) >= map_.points.size())
      throw std::logic_error("RltMapper::step: forced match out of range at iteration " + std::to_string(k));
    result.assignment[observation] = id;
    ++result.global_matches;
  }
  bool loop_closed = false;
  for (std::size_t i = 0; i < frame.points.size(); ++i) {
    PointId& id = result.assignment[i];
    if (id != kNone && k - map_.points[id].last_iteration() >= options_.relaxation_loop_gap) loop_closed = true;
    const bool returned = id != kNone && map_.points[id].last_iteration() < k - options_.match_look_back;
    if (id == kNone) {
      id = create_point(frame.points[i], k);
      ++result.new_points;
    } else {
      record(id, frame.points[i], k, returned);
    }
  }
  return loop_closed;
}

void RltMapper::schedule_relaxation(int k, bool loop_closed, StepResult& result) {
  if (options_.global_relaxation == GlobalRelaxation::OnLoopClosure) {
    if (loop_closed && relax_at_ == kNone) {
      const GroupLevelOptions& level = options_.final_group.enabled ? options_.final_group : options_.temporary_group;
      relax_at_ = std::max(k + level.look_ahead + 1, next_relax_);
    }
    if (relax_at_ != kNone && k >= relax_at_) {
      relax(result);
      // The next closure is relaxed no sooner than relaxation_period from now.
      relax_at_ = kNone;
      next_relax_ = k + options_.relaxation_period;
    }
  } else if (options_.global_relaxation == GlobalRelaxation::Periodic) {
    if (k > map_.first_iteration && (k - map_.first_iteration) % options_.relaxation_period == 0) relax(result);
  }
}

void RltMapper::compute_groups(int k) {
  // Oldest group first, so anchors are refreshed before the groups that build on them (thesis 6.3.3).
  std::sort(queued_groups_.begin(), queued_groups_.end());
  for (GroupId g : queued_groups_) {
    RltGroup& group = map_.groups[g];
    if (group.alive()) map_.compute(group, k, k);
  }
  queued_groups_.clear();
}

void RltMapper::relax(StepResult& result) {
  MapRelaxation relaxation = build_relaxation(map_, options_.relaxation_loss_scale);
  const double trigger = options_.relaxation_trigger_gap;
  // Skipped when every point with a tie over the trigger had one after the previous solve: the
  // groups agree, or disagree only where the loss held a tie off then (a wrong match).
  if (trigger > 0 && std::ranges::includes(held_off_, points_over(relaxation, trigger))) {
    result.relaxation_skipped = true;
    return;
  }
  result.relaxed = true;
  result.relaxation = relaxer_(relaxation.problem);
  // The current pose follows in update_pose, registered to the moved map positions.
  if (!result.relaxation.solved) return;
  apply_relaxation(map_, relaxation);
  if (trigger > 0) held_off_ = points_over(relaxation, trigger);
}

void RltMapper::check_map_frame(int k) {
  // Every point of the first iteration has had its chance to root the map and none could: the
  // map frame (the first observations, thesis 6.3.3) can never be fixed.
  const RltUngroupedList& lowest =
      map_.list(options_.temporary_group.enabled ? GroupLevel::Temporary : GroupLevel::Final);
  const bool first_iteration_tried = lowest.empty() || lowest.front().start > map_.first_iteration;
  if (map_.any_mapped || !failure_.empty() || !first_iteration_tried || options_.provisional_root) return;
  if (options_.preset == Preset::Thesis) {
    failure_ =
        "no group could be anchored to the first iteration's observations (the map frame): fewer than 3 points "
        "were seen there often enough";
    return;
  }
  // Adaptive (beyond the thesis): a sparse start is no failure; the map frame moves on
  // to the first iteration from here that shows three points, and so on until a root forms.
  if (map_.charting.at(k).size() >= 3) move_map_frame(k);
}

void RltMapper::move_map_frame(int k) {
  map_.first_iteration = k;
  map_.forget_map_poses();
  turn_rate_.clear();
  // Provisional positions were in the old frame: placed again from this iteration's pose on.
  for (RltPoint& p : map_.points) {
    if (!p.has_provisional) continue;
    p.has_provisional = false;
    if (map_.global_index->contains(p.id)) map_.global_index->remove(p.id);
  }
  // What is seen now roots the map, as a first iteration's points do: its observations here are
  // the map frame's, and it waits to be grouped from here.
  for (PointId id : map_.charting.at(k)) {
    RltPoint& p = map_.points[id];
    if (p.dynamic || p.merged) continue;
    p.first_observation = *p.observations.at(k);
    for (GroupLevel level : {GroupLevel::Temporary, GroupLevel::Final})
      wait_for_group(map_, id, level, k, options_, true);
  }
}

bool RltMapper::implausible(const Rigid3& registered, const Eigen::Matrix3d& predicted,
                            const std::optional<Rigid3>& dead_reckoned) const {
  // A scan's dead reckoning is never stale: a registration far from its position is rejected.
  if (dead_reckoned && (registered.translation - dead_reckoned->translation).norm() > options_.odometry_max_shift)
    return true;
  // After kMaxRejectedTurns rejections in a row the predicted rotation is taken for stale (a
  // long stretch of predicted rotations drifted past the bound) and the registration stands.
  if (rejected_turns_ >= kMaxRejectedTurns) return false;
  constexpr double kRadPerDeg = std::numbers::pi / 180.0;
  const double turned = Eigen::AngleAxisd(predicted.transpose() * registered.rotation).angle();
  if (dead_reckoned) return turned > options_.odometry_max_turn_deg * kRadPerDeg;
  return options_.preset == Preset::Adaptive && options_.max_turn_deg > 0 &&
         turned > options_.max_turn_deg * kRadPerDeg;
}

void RltMapper::update_pose(const ObservationFrame& frame, StepResult& result) {
  const int k = frame.iteration;
  const std::vector<PointId>& seen = map_.charting.at(k);
  PoseAttempt attempt{k, seen, predict_pose(frame), std::nullopt, MappedPairs{}, false};
  attempt.mapped_registration = register_seen(seen, false, attempt.prediction, attempt.rejected);
  // Fewer than three mapped pairs (adaptive preset): the one or two register_seen(false) found.
  attempt.mapped.count = robot_scratch_.size();
  for (std::size_t i = 0; i < std::min<std::size_t>(attempt.mapped.count, 2); ++i) {
    attempt.mapped.robot[i] = robot_scratch_[i];
    attempt.mapped.world[i] = world_scratch_[i];
  }
  result.pose_source = locate(attempt);
  result.world_T_robot = pose_;
  pose_iteration_ = k;
  // The poses whose registration fixed the rotation measure the turn rate.
  const bool registered = rotation_registered(result.pose_source);
  if (registered) turn_rate_.record(k, pose_.rotation);
  rejected_turns_ = attempt.rejected && !registered ? rejected_turns_ + 1 : 0;
  pose_from_map_ = from_map(result.pose_source);
  if (pose_from_map_) map_.record_map_pose(k, pose_);
  if (options_.match_unmapped || options_.pose_from_unmapped) place_provisional(seen);
}

PoseSource RltMapper::locate(PoseAttempt& a) {
  // The thesis's pose (6.1: RltICP to the mapped points, the map frame at the start) first,
  // then the fallbacks of the adaptive preset and of use_odometry, best-founded first. The order
  // matters beyond preference: by_unmapped_points leaves its pairs in the scratch buffers for the
  // two later provisional cases, and every case reads pose_ as the previous iteration left it.
  using Case = std::optional<Rigid3> (RltMapper::*)(PoseAttempt&);
  static constexpr std::pair<PoseSource, Case> kCases[] = {
      {PoseSource::Start, &RltMapper::at_map_frame},
      {PoseSource::MappedPoints, &RltMapper::by_mapped_points},
      {PoseSource::TwoPoints, &RltMapper::by_two_mapped_points},
      {PoseSource::UnmappedPoints, &RltMapper::by_unmapped_points},
      {PoseSource::Odometry, &RltMapper::by_odometry},
      {PoseSource::TwoUnmappedPoints, &RltMapper::by_two_unmapped_points},
      {PoseSource::OnePoint, &RltMapper::by_one_mapped_point},
      {PoseSource::OneUnmappedPoint, &RltMapper::by_unmapped_centroid},
  };
  for (const auto& [source, attempt] : kCases)
    if (const std::optional<Rigid3> pose = (this->*attempt)(a)) {
      pose_ = *pose;
      return source;
    }
  return PoseSource::Held;  // no registration possible: the previous pose is kept
}

std::optional<Rigid3> RltMapper::at_map_frame(PoseAttempt& a) {
  // The first iteration's robot frame is the map frame (thesis 6.3.3): the identity.
  if (a.k != map_.first_iteration) return std::nullopt;
  return Rigid3::identity();
}

std::optional<Rigid3> RltMapper::by_mapped_points(PoseAttempt& a) {
  // RltICP of the observations to their points' map positions (thesis 6.1).
  return a.mapped_registration;
}

std::optional<Rigid3> RltMapper::by_two_mapped_points(PoseAttempt& a) {
  // Deviation (adaptive two_point_registration): exactly two mapped points, the rotation about
  // their line from the latest map-registered pose. Not with dead reckoning, which does better.
  if (a.prediction.dead_reckoned || a.mapped.count != 2) return std::nullopt;
  return map_.pose_from_two_points(a.mapped.robot[0], a.mapped.robot[1], a.mapped.world[0], a.mapped.world[1]);
}

std::optional<Rigid3> RltMapper::by_unmapped_points(PoseAttempt& a) {
  // Deviation (pose_from_unmapped): RltICP to the provisional positions too.
  if (!options_.pose_from_unmapped) return std::nullopt;
  const std::optional<Rigid3> pose = register_seen(a.seen, true, a.prediction, a.rejected);
  if (!pose) return std::nullopt;
  return average_provisional_on(options_) ? weigh_provisional(*pose, a.prediction.rotation) : *pose;
}

std::optional<Rigid3> RltMapper::by_odometry(PoseAttempt& a) {
  // Fewer than three points to register (use_odometry): dead reckoning rather than a pose from
  // one or two points.
  return a.prediction.dead_reckoned;
}

std::optional<Rigid3> RltMapper::by_two_unmapped_points(PoseAttempt& a) {
  // Deviation (adaptive average_provisional): two pairs, mapped or provisional, that the last
  // register_seen left in the scratch buffers; as by_two_mapped_points, about their line.
  if (!average_provisional_on(options_) || robot_scratch_.size() != 2) return std::nullopt;
  const std::optional<Rigid3> pose =
      register_two_points(robot_scratch_[0], robot_scratch_[1], world_scratch_[0], world_scratch_[1], pose_.rotation,
                          pose_.rotation.col(1), map_.max_line_sine());
  if (!pose) return std::nullopt;
  return weigh_provisional(*pose, a.prediction.rotation);
}

std::optional<Rigid3> RltMapper::by_one_mapped_point(PoseAttempt& a) {
  // Deviation (adaptive): one mapped point, the rotation turned on at the measured rate, the
  // translation from that point.
  if (a.mapped.count < 1) return std::nullopt;
  return map_.pose_from_one_point(a.mapped.robot[0], a.mapped.world[0], turn_rate_, a.k);
}

std::optional<Rigid3> RltMapper::by_unmapped_centroid(PoseAttempt& a) {
  // Deviation (adaptive average_provisional): one pair, two on a line too steep for two-point
  // registration, or a rejected registration. The rotation turns on at the measured rate
  // (turn_rate_window; none: the latest rotation); the position from the pairs' centroid (one
  // pair: that pair; a rejected registration's swapped pair leaves it where it was).
  if (!average_provisional_on(options_) || robot_scratch_.empty()) return std::nullopt;
  return register_centroids(robot_scratch_, world_scratch_, a.prediction.rotation);
}

RltMapper::PosePrediction RltMapper::predict_pose(const ObservationFrame& frame) const {
  const int k = frame.iteration;
  // With use_odometry, where this frame's dead reckoning puts the robot (the latest pose moved by it).
  std::optional<Rigid3> dead_reckoned;
  if (options_.use_odometry && frame.odometry && pose_iteration_ == k - 1) dead_reckoned = pose_ * *frame.odometry;
  // The rotation the robot has now: dead-reckoned, or if it turned on at the measured rate
  // (adaptive; otherwise the latest rotation).
  const Eigen::Matrix3d predicted =
      dead_reckoned ? dead_reckoned->rotation : Eigen::Matrix3d(pose_.rotation * turn_rate_.turn(pose_iteration_, k));
  return {dead_reckoned, predicted};
}

std::optional<Rigid3> RltMapper::register_seen(const std::vector<PointId>& seen, bool provisional,
                                               const PosePrediction& prediction, bool& rejected) {
  std::vector<Eigen::Vector3d>&robot = robot_scratch_, &world = world_scratch_;
  robot.clear();
  world.clear();
  for (PointId id : seen) {
    const RltPoint& p = map_.points[id];
    if (p.dynamic || p.merged) continue;
    if (p.has_global) {
      robot.push_back(p.observations.latest().p);
      world.push_back(p.global);
    } else if (provisional && p.has_provisional) {
      robot.push_back(p.observations.latest().p);
      world.push_back(p.provisional);
    }
  }
  auto registered = rlt_icp(robot, world);
  // Deviation (adaptive; use_odometry): a registration that turns the robot
  // further from the predicted rotation than max_turn_deg, or strays from the dead-reckoned
  // pose, is a mismatch, not a motion (implausible).
  if (registered && implausible(*registered, prediction.rotation, prediction.dead_reckoned)) {
    registered.reset();
    rejected = true;
  }
  return registered;
}

Rigid3 RltMapper::weigh_provisional(const Rigid3& registered, const Eigen::Matrix3d& predicted) const {
  // Deviation (adaptive, provisional_rotation_weight): the chain through provisional positions
  // takes only part of each registration's rotation, the rest from the turn-rate prediction, and
  // its position from the pairs (left in the scratch buffers by register_seen) at their centroid.
  return register_centroids(robot_scratch_, world_scratch_,
                            interpolate_rotation(predicted, registered.rotation, options_.provisional_rotation_weight));
}

void RltMapper::place_provisional(const std::vector<PointId>& seen) {
  for (PointId id : seen) {
    RltPoint& p = map_.points[id];
    if (p.has_global || p.dynamic || p.merged) continue;
    const Eigen::Vector3d placed = pose_ * p.observations.latest().p;
    if (average_provisional_on(options_) && p.has_provisional) {
      p.provisional += (placed - p.provisional) / ++p.provisional_placements;  // the running mean
    } else {
      p.provisional = placed;
      p.provisional_placements = 1;
    }
    p.has_provisional = true;
    if (options_.match_unmapped) map_.global_index->place(id, p.provisional);
  }
}

}  // namespace relslam::point
