#include "relslam/point/rlt_mapper.hpp"

#include "relslam/point/rlt_icp.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
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

constexpr double kBasisEpsilon = 1e-6;  // relative degeneracy tolerance of one iteration's basis [C]

const PointSlamOptions& checked(const PointSlamOptions& options) {
  const auto issues = check(options);
  if (!issues.empty())
    throw std::logic_error("RltMapper: invalid options: " + issues.front().field + ": " + issues.front().problem);
  return options;
}

}  // namespace

RltMapper::RltMapper(const PointSlamOptions& options)
    : options_(checked(options)),
      charting_(options.charting_capacity),
      global_index_(options.global_cell_size, options.global_bound),
      matcher_(options_) {}

StepResult RltMapper::step(const ObservationFrame& frame) {
  const int k = frame.iteration;
  if (last_iteration_ != kNone && k <= last_iteration_)
    throw std::logic_error("RltMapper::step: iteration " + std::to_string(k) + " after " + std::to_string(last_iteration_));
  for (const Eigen::Vector3d& p : frame.points)
    if (!p.allFinite()) throw std::logic_error("RltMapper::step: non-finite observation at iteration " + std::to_string(k));
  if (first_iteration_ == kNone) first_iteration_ = k;
  last_iteration_ = k;

  StepResult result;
  result.iteration = k;
  changed_ = &result.changed;
  auto clock = Clock::now();

  // [init] Local candidates: latest observations of points seen in the last few iterations.
  charting_.begin_iteration(k);
  build_local_index(k);
  result.timings.init_ms = ms_since(clock);

  // [load] Local, then global matching, then new RltPoints (thesis 6.2.5).
  const MatchResult& match = matcher_.match(frame.points, k, global_index_, points_, pose_);
  result.assignment = match.assigned;
  result.local_matches = match.local;
  result.global_matches = match.global;
  for (std::size_t i = 0; i < frame.points.size(); ++i) {
    PointId& id = result.assignment[i];
    const bool returned = id != kNone && points_[id].last_iteration() < k - options_.match_look_back;
    if (id == kNone) {
      id = create_point(frame.points[i], k);
      ++result.new_points;
    } else {
      record(id, frame.points[i], k, returned);
    }
  }
  result.timings.load_ms = ms_since(clock);

  // [compute] Groups with a new observation, oldest first so anchors are fresh (spec 5.5).
  compute_groups(k);
  result.timings.compute_ms = ms_since(clock);

  // [creation] Temporary, then final groups (thesis 6.4.3), then clean-up (6.5.5).
  create_groups(k, result);
  if (k % options_.temporary_cleanup_period == 0) retire_redundant_temporary_groups(k);
  result.timings.create_ms = ms_since(clock);

  // [pose] Current position (thesis 6.1): used for the next global matching and for metrics.
  update_pose(k, result);
  result.timings.pose_ms = ms_since(clock);
  changed_ = nullptr;
  return result;
}

void RltMapper::build_local_index(int k) {
  scratch_ids_.clear();
  charting_.enumerate_unique(k - options_.match_look_back, k - 1, scratch_ids_);
  local_candidates_.clear();
  // The latest observation, wherever in the window it was (thesis 6.2.3). Dynamic points stay
  // locally matchable, so a mover does not start a new RltPoint every frame (spec 5.4).
  for (PointId id : scratch_ids_) {
    const RltPoint& p = points_[id];
    if (!p.merged) local_candidates_.push_back({id, p.observations.latest().p, p.observations.latest().iteration});
  }
  matcher_.prepare(local_candidates_, k);
}

PointId RltMapper::create_point(const Eigen::Vector3d& p, int k) {
  const auto id = static_cast<PointId>(points_.size());
  points_.emplace_back(options_.ring_capacity);
  RltPoint& point = points_.back();
  point.id = id;
  point.creation_iteration = k;
  point.first_observation = {p, k};
  record(id, p, k, true);
  return id;
}

void RltMapper::record(PointId id, const Eigen::Vector3d& p, int k, bool returned) {
  RltPoint& point = points_[id];
  point.observations.push({p, k});
  point.interval.add(k);
  charting_.add(id);
  // A point starting a visible run while still ungrouped at a level waits in that level's list,
  // its run's start standing in for the creation iteration. New points always enter both.
  if (returned && !point.dynamic) {
    if (!point.temporary_grouped && !point.final_grouped) temporary_list_.push(id, k);
    if (!point.final_grouped) final_list_.push(id, k);
  }
  // Notify its groups (thesis 6.3.3): each is computed once this iteration.
  if (group_queued_at_.size() < groups_.size()) group_queued_at_.resize(groups_.size(), kNone);
  for (const RltGroupRef& ref : point.groups) {
    if (!groups_[ref.group].alive() || group_queued_at_[ref.group] == k) continue;
    group_queued_at_[ref.group] = k;
    queued_groups_.push_back(ref.group);
  }
}

void RltMapper::compute_groups(int k) {
  std::sort(queued_groups_.begin(), queued_groups_.end());
  for (GroupId g : queued_groups_) {
    RltGroup& group = groups_[g];
    if (group.accumulate(points_, k, k, kBasisEpsilon)) anchor(group);
  }
  queued_groups_.clear();
}

void RltMapper::anchor(RltGroup& group) {
  const auto world_T_group = group.registration(points_, first_iteration_);
  if (!world_T_group) return;
  for (std::size_t i = 0; i < group.members().size(); ++i) {
    const PointId id = group.members()[i];
    const RltPoint& p = points_[id];
    // Anchors are registration sources and never rewritten by this group (spec 5.5).
    if (group.anchor(static_cast<int>(i)) || p.owner != group.id() || p.dynamic || p.merged) continue;
    set_global(id, *world_T_group * group.relative(static_cast<int>(i)));
  }
}

void RltMapper::set_global(PointId id, const Eigen::Vector3d& g) {
  RltPoint& p = points_[id];
  p.global = g;
  p.has_global = true;
  p.has_provisional = false;
  any_mapped_ = true;
  global_index_.place(id, g);
  mark_changed(id);
}

void RltMapper::mark_changed(PointId id) {
  if (!changed_) return;
  if (changed_at_.size() <= static_cast<std::size_t>(id)) changed_at_.resize(static_cast<std::size_t>(id) * 2 + 16, kNone);
  if (changed_at_[id] == last_iteration_) return;
  changed_at_[id] = last_iteration_;
  changed_->push_back(id);
}

void RltMapper::create_groups(int k, StepResult& result) {
  for (GroupLevel level : {GroupLevel::Temporary, GroupLevel::Final}) {
    RltUngroupedList& waiting = list(level);
    const int look_ahead = level_options(level).look_ahead;
    // Process every entry that is ready; the list is in start order (spec 5.6, A40).
    while (!waiting.empty() && k >= waiting.front().start + look_ahead) {
      const RltUngroupedList::Entry entry = waiting.front();
      waiting.pop_front();
      if (try_create(level, entry, k)) ++result.groups_created;
    }
  }
  // Every point of the first iteration has had its chance to root the map and none could: the
  // map frame (the first observations, thesis 6.3.3) can never be fixed.
  const bool first_iteration_tried = temporary_list_.empty() || temporary_list_.front().start > first_iteration_;
  if (!any_mapped_ && failure_.empty() && first_iteration_tried)
    failure_ = "no group could be anchored to the first iteration's observations (the map frame): fewer than 3 points "
               "were seen there often enough";
}

bool RltMapper::try_create(GroupLevel level, const RltUngroupedList::Entry& entry, int k) {
  const RltPoint& c = points_[entry.id];
  if (c.dynamic || c.merged) return false;
  LevelContext context;
  context.level = level;
  context.options = &level_options(level);
  context.ungrouped = &list(level);
  context.level_mapped = level == GroupLevel::Temporary ? any_mapped_ : stats_.final_created > 0;
  context.first_iteration = first_iteration_;
  auto plan = planner_.plan(entry.id, entry.start, k, context, points_, charting_, options_.basis, options_.min_basis_ratio);
  if (!plan) return false;

  const auto id = static_cast<GroupId>(groups_.size());
  groups_.emplace_back(id, level, entry.start, k, plan->members, plan->anchor, plan->basis, plan->root);
  ++stats_.created;
  ++stats_.alive;
  if (level == GroupLevel::Final) ++stats_.final_created;
  if (level == GroupLevel::Temporary) {
    ++stats_.temporary_alive;
    temporary_to_review_.push_back(id);
  }

  for (std::size_t i = 0; i < plan->members.size(); ++i) {
    RltPoint& p = points_[plan->members[i]];
    p.groups.push_back({id, static_cast<int>(i)});
    if (plan->anchor[i]) continue;
    list(level).remove(p.id);
    // Ownership (spec 5.6): a final group always takes its new members; a temporary group
    // only those no final group owns. Final groups thus map everything they hold (6.5.5).
    if (level == GroupLevel::Final) {
      p.final_grouped = true;
      p.owner = id;
    } else {
      p.temporary_grouped = true;
      if (!p.final_grouped) p.owner = id;
    }
  }
  RltGroup& group = groups_.back();
  if (group.accumulate(points_, entry.start, k, kBasisEpsilon)) anchor(group);
  return true;
}

void RltMapper::retire_redundant_temporary_groups(int k) {
  // A temporary group's new members are offered to final groups within the final look-ahead;
  // after that, a group that owns none of its members maps nothing and only costs time.
  const int settled = k - options_.final_group.look_ahead - options_.temporary_group.look_ahead;
  while (!temporary_to_review_.empty() && groups_[temporary_to_review_.front()].built_at() <= settled) {
    RltGroup& group = groups_[temporary_to_review_.front()];
    temporary_to_review_.pop_front();
    const bool owns_any = std::any_of(group.members().begin(), group.members().end(), [&](PointId id) {
      return points_[id].owner == group.id();
    });
    if (owns_any) continue;  // it still maps a point no final group took: kept for good
    group.retire();
    --stats_.alive;
    --stats_.temporary_alive;
    for (PointId id : group.members()) {
      auto& refs = points_[id].groups;
      refs.erase(std::remove_if(refs.begin(), refs.end(), [&](const RltGroupRef& r) { return r.group == group.id(); }),
                 refs.end());
    }
  }
}

void RltMapper::update_pose(int k, StepResult& result) {
  const std::vector<PointId>& seen = charting_.at(k);
  auto register_to = [&](bool provisional) -> std::optional<Rigid3> {
    std::vector<Eigen::Vector3d> robot, world;
    for (PointId id : seen) {
      const RltPoint& p = points_[id];
      if (p.dynamic || p.merged) continue;
      if (p.has_global) {
        robot.push_back(p.observations.latest().p);
        world.push_back(p.global);
      } else if (provisional && p.has_provisional) {
        robot.push_back(p.observations.latest().p);
        world.push_back(p.provisional);
      }
    }
    return rlt_icp(robot, world);
  };

  if (k == first_iteration_) {
    pose_ = Rigid3::identity();
    result.pose_source = PoseSource::Start;
  } else if (auto pose = register_to(false)) {
    pose_ = *pose;
    result.pose_source = PoseSource::MappedPoints;
  } else if (options_.pose_from_unmapped && (pose = register_to(true))) {
    pose_ = *pose;
    result.pose_source = PoseSource::UnmappedPoints;
  } else {
    result.pose_source = PoseSource::Held;
  }
  result.world_T_robot = pose_;

  // Provisional positions of the unmapped points seen now (Deviation, see options).
  if (options_.match_unmapped || options_.pose_from_unmapped)
    for (PointId id : seen) {
      RltPoint& p = points_[id];
      if (p.has_global || p.dynamic || p.merged) continue;
      p.provisional = pose_ * p.observations.latest().p;
      p.has_provisional = true;
      if (options_.match_unmapped) global_index_.place(id, p.provisional);
    }
}

}  // namespace relslam::point
