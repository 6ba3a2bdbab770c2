#pragma once
// RltGroup (thesis 6.3.3): a fixed set of RltPoints seen together and their averaged
// positions in the frame of three basis points.

#include "relslam/core/rigid.hpp"
#include "relslam/point/basis.hpp"
#include "relslam/point/rlt_interval.hpp"
#include "relslam/point/rlt_point.hpp"

#include <array>
#include <optional>
#include <vector>

namespace relslam::point {

enum class GroupLevel : unsigned char {
  Temporary,  // short look-ahead: maps new points quickly (thesis 6.5.5)
  Final,      // long look-ahead: the groups the map's accuracy rests on
  Level3,     // formed when a point leaves the view, over its whole visible run (thesis 6.5.5)
};

// How a group finds its place on the map (thesis 6.3.3 step 4).
enum class Registration : unsigned char {
  Anchors,            // its previously mapped members (anchors) to their map positions
  FirstObservations,  // the root group: its members seen at the first iteration to those
                      // observations (the robot frame at the first iteration is the world frame)
  WorldPositions,     // a provisional root (PointSlamOptions::provisional_root): its members to
                      // whatever world position they have, provisional until mapped
};

// Invariant: members, anchor flags and basis never change after construction (a change means a
// new group, thesis 6.3.3), so running sums stay valid; sums only ever include iterations in
// which every member was observed. The one exception is a merge (thesis 6.5.2), which swaps a
// member for a point holding the very same observations.
class RltGroup {
 public:
  RltGroup(GroupId id, GroupLevel level, int c0, int built_at, std::vector<PointId> members, std::vector<bool> anchor,
           std::array<int, 3> basis, Registration registration);

  // Adds every iteration in [from, to] not yet used in which all members were observed
  // (thesis 6.3.3 steps 1–2); an iteration whose basis is degenerate is skipped. Returns
  // whether anything was added. O(members) per iteration.
  bool accumulate(const std::vector<RltPoint>& points, int from, int to, double basis_epsilon);

  // world_T_group from the averaged positions (thesis 6.3.3 step 4), as registration() says.
  // Nothing before the first accumulation or with fewer than 3 usable pairs.
  std::optional<Rigid3> registration(const std::vector<RltPoint>& points, int first_iteration) const;
  // The pairs registration() registers: each usable member's averaged position in the basis
  // frame (`from`) and its place in the world frame (`to`), as registration() says; valid once
  // iterations_used() > 0.
  void registration_pairs(const std::vector<RltPoint>& points, int first_iteration, std::vector<Eigen::Vector3d>& from,
                          std::vector<Eigen::Vector3d>& to) const;

  GroupId id() const { return id_; }
  GroupLevel level() const { return level_; }
  int c0() const { return c0_; }
  int built_at() const { return built_at_; }
  bool root() const { return registration_ != Registration::Anchors; }
  Registration registration() const { return registration_; }
  bool alive() const { return alive_; }
  void retire() { alive_ = false; }
  // A merge: the member becomes `id`, an anchor (it keeps its own map position).
  void replace_member(int member, PointId id) {
    members_[member] = id;
    anchor_[member] = true;
  }
  const std::vector<PointId>& members() const { return members_; }
  bool anchor(int member) const { return anchor_[member]; }
  const std::array<int, 3>& basis() const { return basis_; }
  int iterations_used() const { return used_; }
  const RltInterval& computed_on() const { return computed_on_; }
  // Averaged position of a member in the basis frame; valid once iterations_used() > 0.
  Eigen::Vector3d relative(int member) const { return sum_[member] / used_; }

 private:
  GroupId id_;
  GroupLevel level_;
  int c0_;
  int built_at_;
  std::vector<PointId> members_;
  std::vector<bool> anchor_;
  std::array<int, 3> basis_;
  Registration registration_;
  bool alive_ = true;
  std::vector<Eigen::Vector3d> sum_;
  int used_ = 0;
  RltInterval computed_on_;
  std::vector<const Point*> scratch_;  // one iteration's observations, reused
};

}  // namespace relslam::point
