#include "relslam/point/rlt_map.hpp"

#include "relslam/point/rlt_icp.hpp"
#include "relslam/point/rotation_fit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace relslam::point {
namespace {

constexpr double kBasisEpsilon = 1e-6;  // relative degeneracy tolerance of one iteration's basis [C]

// The robot's up axis (+y of the robot frame, observation.hpp) in the map frame at a pose.
Eigen::Vector3d up_in_world(const Rigid3& world_T_robot) { return world_T_robot.rotation.col(1); }

}  // namespace

RltMap::RltMap(const PointSlamOptions& options)
    : charting(options.charting_capacity),
      global_index(spatial::make_global_index(options.global_index, options.global_cell_size,
                                              std::max(options.global_bound, options.merge_bound))),
      two_point_(two_point_registration_on(options)),
      max_line_sine_(std::sin(options.two_point_max_elevation_deg * std::numbers::pi / 180.0)),
      pose_window_(history_window(options)),
      root_window_(root_rotation_window_on(options)) {}

void RltMap::compute(RltGroup& group, int from, int k) {
  if (group.accumulate(points, from, k, kBasisEpsilon)) anchor(group);
}

void RltMap::anchor(RltGroup& group) {
  std::optional<Rigid3> world_T_group;
  if (root_window_ > 0 && group.registration() == Registration::FirstObservations) world_T_group = register_root(group);
  if (!world_T_group) world_T_group = group.registration(points, first_iteration);
  if (!world_T_group && two_point_) world_T_group = register_on_two_anchors(group);
  if (!world_T_group) return;
  for (std::size_t i = 0; i < group.members().size(); ++i) {
    const PointId id = group.members()[i];
    const RltPoint& p = points[id];
    if (group.anchor(static_cast<int>(i)) || p.owner != group.id() || p.dynamic || p.merged) continue;
    set_global(id, *world_T_group * group.relative(static_cast<int>(i)));
  }
}

std::optional<Rigid3> RltMap::register_on_two_anchors(const RltGroup& group) {
  if (group.registration() != Registration::Anchors || group.iterations_used() == 0) return std::nullopt;
  std::array<int, 2> pair{};
  int anchors = 0;
  for (std::size_t i = 0; i < group.members().size(); ++i) {
    if (!group.anchor(static_cast<int>(i)) || !points[group.members()[i]].on_map()) continue;
    if (anchors == 2) return std::nullopt;  // three or more: registration() failed for another reason
    pair[anchors++] = static_cast<int>(i);
  }
  if (anchors != 2 || map_poses_.empty()) return std::nullopt;
  const auto& basis = group.basis();
  TwoAnchorPrior& prior = two_anchor_priors_[group.id()];
  for (const auto& [t, world_T_robot] : map_poses_) {  // oldest first: each pose is added once
    if (t <= prior.last) continue;
    prior.last = t;
    if (!group.computed_on().contains(t)) continue;
    const Point* b0 = points[group.members()[basis[0]]].observations.at(t);
    const Point* b1 = points[group.members()[basis[1]]].observations.at(t);
    const Point* b2 = points[group.members()[basis[2]]].observations.at(t);
    if (!b0 || !b1 || !b2) continue;
    const auto frame = basis_frame(b0->p, b1->p, b2->p, kBasisEpsilon);
    if (!frame) continue;
    // world_R_group = world_R_robot(t) * robot_R_basis(t); the basis frame maps robot to basis.
    prior.sum += world_T_robot.rotation * frame->rotation.transpose();
    ++prior.count;
  }
  if (prior.count == 0) return std::nullopt;
  return register_two_points(group.relative(pair[0]), group.relative(pair[1]), points[group.members()[pair[0]]].global,
                             points[group.members()[pair[1]]].global, mean_rotation(prior.sum),
                             up_in_world(map_poses_.back().second), max_line_sine_);
}

std::optional<Rigid3> RltMap::register_root(const RltGroup& group) {
  if (group.iterations_used() == 0) return std::nullopt;
  thread_local std::vector<Eigen::Vector3d> from, to;
  RootRotation& root = root_rotations_[group.id()];
  if (!root.settled) {
    // robot_R_group at each iteration of the window the group used: its averaged positions
    // registered to that iteration's observations. The map frame is the robot frame at
    // first_iteration, so world_R_group is the line's value there.
    thread_local std::vector<std::pair<int, Eigen::Matrix3d>> rotations;
    rotations.clear();
    const int window_end = first_iteration + root_window_;
    for (int t = first_iteration; t <= std::min(window_end, group.computed_on().last()); ++t) {
      if (!group.computed_on().contains(t)) continue;
      from.clear();
      to.clear();
      for (std::size_t i = 0; i < group.members().size(); ++i) {
        const RltPoint& p = points[group.members()[i]];
        const Point* observed = p.observations.at(t);
        if (!observed || p.dynamic || p.merged) continue;
        from.push_back(group.relative(static_cast<int>(i)));
        to.push_back(observed->p);
      }
      if (const auto robot_T_group = rlt_icp(from, to)) rotations.emplace_back(t, robot_T_group->rotation);
    }
    const auto fitted = fitted_rotation(rotations, first_iteration);
    if (!fitted) return std::nullopt;
    root.rotation = *fitted;
    root.settled = group.computed_on().last() > window_end;
  }
  group.registration_pairs(points, first_iteration, from, to);
  if (from.size() < 3) return std::nullopt;
  return register_centroids(from, to, root.rotation);
}

void RltMap::record_map_pose(int k, const Rigid3& world_T_robot) {
  if (!two_point_) return;
  map_poses_.emplace_back(k, world_T_robot);
  while (map_poses_.front().first < k - pose_window_) map_poses_.pop_front();
}

std::optional<Rigid3> RltMap::pose_from_two_points(const Eigen::Vector3d& robot0, const Eigen::Vector3d& robot1,
                                                   const Eigen::Vector3d& world0,
                                                   const Eigen::Vector3d& world1) const {
  if (!two_point_ || map_poses_.empty()) return std::nullopt;
  const Rigid3& prior = map_poses_.back().second;
  return register_two_points(robot0, robot1, world0, world1, prior.rotation, up_in_world(prior), max_line_sine_);
}

std::optional<Rigid3> RltMap::pose_from_one_point(const Eigen::Vector3d& robot, const Eigen::Vector3d& world,
                                                  const TurnRate& turn_rate, int k) const {
  if (!two_point_ || map_poses_.empty()) return std::nullopt;
  const auto& [t, latest] = map_poses_.back();
  return register_one_point(robot, world, latest.rotation * turn_rate.turn(t, k));
}

void RltMap::set_global(PointId id, const Eigen::Vector3d& g) {
  RltPoint& p = points[id];
  p.global = g;
  p.has_global = true;
  p.has_provisional = false;
  any_mapped = true;
  global_index->place(id, g);
  mark_changed(id);
}

void RltMap::retire(RltGroup& group) {
  group.retire();
  --stats.alive;
  stats.alive_members -= static_cast<long long>(group.members().size());
  if (group.level() == GroupLevel::Temporary) --stats.temporary_alive;
  for (PointId id : group.members()) {
    auto& refs = points[id].groups;
    refs.erase(std::remove_if(refs.begin(), refs.end(), [&](const RltGroupRef& r) { return r.group == group.id(); }),
               refs.end());
  }
}

void RltMap::mark_changed(PointId id) {
  if (changed_at_.size() <= static_cast<std::size_t>(id))
    changed_at_.resize(static_cast<std::size_t>(id) * 2 + 16, kNone);
  if (changed_at_[id] == iteration) return;
  changed_at_[id] = iteration;
  changed_.push_back(id);
}

std::vector<PointId> RltMap::take_changed() {
  std::vector<PointId> changed;
  changed.swap(changed_);
  return changed;
}

}  // namespace relslam::point
