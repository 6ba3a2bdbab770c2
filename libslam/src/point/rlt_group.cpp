#include "relslam/point/rlt_group.hpp"

#include "relslam/point/rlt_icp.hpp"

#include <stdexcept>

namespace relslam::point {
namespace {

// ObservationRing::at's two usual answers without the call: a group is computed at the current
// iteration (thesis 6.3.3), where each member was either just observed or not since.
const Point* observation_at(const ObservationRing& ring, int t) {
  if (ring.empty() || ring.latest().iteration < t) return nullptr;
  if (ring.latest().iteration == t) return &ring.latest();
  return ring.at(t);
}

}  // namespace

RltGroup::RltGroup(GroupId id, GroupLevel level, int c0, int built_at, std::vector<PointId> members,
                   std::vector<bool> anchor, std::array<int, 3> basis, Registration registration)
    : id_(id),
      level_(level),
      c0_(c0),
      built_at_(built_at),
      members_(std::move(members)),
      anchor_(std::move(anchor)),
      basis_(basis),
      registration_(registration),
      sum_(members_.size(), Eigen::Vector3d::Zero()) {
  if (anchor_.size() != members_.size()) throw std::logic_error("RltGroup: one anchor flag per member");
  for (int b : basis_)
    if (b < 0 || b >= static_cast<int>(members_.size())) throw std::logic_error("RltGroup: basis index out of range");
}

bool RltGroup::accumulate(const std::vector<RltPoint>& points, int from, int to, double basis_epsilon) {
  bool added = false;
  scratch_.resize(members_.size());
  // Over a range (a new group, a merge: up to look-ahead + 1 iterations), each member's ring is
  // walked forward once instead of searched for every iteration.
  thread_local std::vector<int> next;  // per member: its first observation at or after t
  const bool range = to > from;
  if (range) {
    next.resize(members_.size());
    for (std::size_t i = 0; i < members_.size(); ++i) next[i] = points[members_[i]].observations.lower_bound(from);
  }
  for (int t = from; t <= to; ++t) {
    if (!computed_on_.empty() && t <= computed_on_.last() && computed_on_.contains(t)) continue;
    bool all_present = true;
    for (std::size_t i = 0; i < members_.size() && all_present; ++i) {
      const ObservationRing& ring = points[members_[i]].observations;
      if (range) {
        int& j = next[i];
        while (j < ring.size() && ring[j].iteration < t) ++j;
        scratch_[i] = j < ring.size() && ring[j].iteration == t ? &ring[j] : nullptr;
      } else {
        scratch_[i] = observation_at(ring, t);
      }
      all_present = scratch_[i] != nullptr;
    }
    if (!all_present) continue;  // thesis 6.3.3: only iterations with every member observed
    const auto frame =
        basis_frame(scratch_[basis_[0]]->p, scratch_[basis_[1]]->p, scratch_[basis_[2]]->p, basis_epsilon);
    if (!frame) continue;
    for (std::size_t i = 0; i < members_.size(); ++i) sum_[i] += (*frame)(scratch_[i]->p);
    ++used_;
    computed_on_.insert(t);
    added = true;
  }
  return added;
}

std::optional<Rigid3> RltGroup::registration(const std::vector<RltPoint>& points, int first_iteration) const {
  if (used_ == 0) return std::nullopt;
  // Reused between calls: every anchored group registers each iteration it is computed.
  thread_local std::vector<Eigen::Vector3d> from, to;
  registration_pairs(points, first_iteration, from, to);
  return rlt_icp(from, to);
}

void RltGroup::registration_pairs(const std::vector<RltPoint>& points, int first_iteration,
                                  std::vector<Eigen::Vector3d>& from, std::vector<Eigen::Vector3d>& to) const {
  from.clear();
  to.clear();
  for (std::size_t i = 0; i < members_.size(); ++i) {
    const RltPoint& p = points[members_[i]];
    if (registration_ == Registration::FirstObservations) {
      if (p.first_observation.iteration != first_iteration || p.dynamic || p.merged) continue;
      from.push_back(relative(static_cast<int>(i)));
      to.push_back(p.first_observation.p);  // robot frame at the first iteration = world frame
    } else if (registration_ == Registration::WorldPositions) {
      // Provisional positions until the group itself maps its members, then their map positions.
      if (p.dynamic || p.merged || !(p.has_global || p.has_provisional)) continue;
      from.push_back(relative(static_cast<int>(i)));
      to.push_back(p.has_global ? p.global : p.provisional);
    } else if (anchor_[i] && p.on_map()) {
      from.push_back(relative(static_cast<int>(i)));
      to.push_back(p.global);
    }
  }
}

}  // namespace relslam::point
