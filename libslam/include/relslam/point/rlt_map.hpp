#pragma once
// The map of the Relative Point algorithm: the master storage of RltPoints and RltGroups that
// the thesis keeps in RltMapper (6.4.3), with the indexes kept beside them. Eigen only.

#include "relslam/point/options.hpp"
#include "relslam/point/rlt_group.hpp"
#include "relslam/point/rlt_point.hpp"
#include "relslam/point/rlt_point_charting.hpp"
#include "relslam/point/rlt_ungrouped_list.hpp"
#include "relslam/point/turn_rate.hpp"
#include "relslam/spatial/global_index.hpp"

#include <deque>
#include <memory>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace relslam::point {

struct GroupStats {
  int created = 0;  // every group ever built
  int alive = 0;
  int temporary_alive = 0;
  long long alive_members = 0;  // members of the alive groups, summed (thesis Fig 123: group size)
  int final_created = 0;
  int level3_created = 0;
  int dynamic_points = 0;  // flagged so far
  int merged_points = 0;   // merged so far
};

// RltMapper's steps, group creation (group_creation.hpp) and RltPoint merging
// (rlt_point_merging.hpp) all edit this one map. Points and groups are never deleted, only
// flagged (thesis 6.4.3: master lists, no garbage collection), so ids index the vectors.
// Invariants, kept by the methods below (the edits that change more than one part): a point's
// map position and the global index agree; a retired group is in no member's refs; `stats`
// counts the alive groups and their members; `changed` lists each point whose map state
// changed this iteration once.
struct RltMap {
  // Sized from the options (charting capacity, global index kind and cell).
  explicit RltMap(const PointSlamOptions& options);

  std::vector<RltPoint> points;
  std::vector<RltGroup> groups;
  RltPointCharting charting;
  // Positions of the mapped points (and, with match_unmapped, provisional ones), for global
  // matching and merging (thesis 6.5.1).
  std::unique_ptr<spatial::GlobalIndex> global_index;
  // RltPoints waiting for a group, one list per level (thesis 6.4.2).
  RltUngroupedList temporary_list, final_list;
  GroupStats stats;
  int first_iteration = kNone;  // its robot frame is the map frame (thesis 6.3.3)
  bool any_mapped = false;      // some point has had a map position
  int iteration = kNone;        // the iteration being processed

  RltUngroupedList& list(GroupLevel level) { return level == GroupLevel::Temporary ? temporary_list : final_list; }

  // ComputeRltGroup (thesis 6.3.3): accumulates the iterations of [from, k] the group can use
  // and, if any was added, anchors it.
  void compute(RltGroup& group, int from, int k);
  // Thesis 6.3.3 step 4: registers the group (as its Registration says) and writes the map
  // position of every member it owns; anchors are registration sources and never rewritten by
  // this group (thesis 6.3.3).
  void anchor(RltGroup& group);
  // Deviation (adaptive preset, PointSlamOptions::two_point_registration): the robot
  // poses registered to the map (the map frame's, to three or more mapped points, or to two),
  // kept for history_window iterations as the priors of two-point registration. A no-op when it
  // is off.
  void record_map_pose(int k, const Rigid3& world_T_robot);
  // world_T_robot from two mapped points in view (their robot-frame observations and map
  // positions), the rotation about their line from the latest recorded pose. Nothing when
  // two-point registration is off, before the first recorded pose, or for a steep line.
  std::optional<Rigid3> pose_from_two_points(const Eigen::Vector3d& robot0, const Eigen::Vector3d& robot1,
                                             const Eigen::Vector3d& world0, const Eigen::Vector3d& world1) const;
  // world_T_robot at iteration k from one mapped point in view: the latest recorded pose's
  // rotation, turned on to k at `turn_rate`, the translation putting the observation on the map
  // position. Nothing when two-point registration is off or before the first recorded pose.
  std::optional<Rigid3> pose_from_one_point(const Eigen::Vector3d& robot, const Eigen::Vector3d& world,
                                            const TurnRate& turn_rate, int k) const;
  // Sine of two_point_max_elevation_deg: the steepest line two-point registration accepts.
  double max_line_sine() const { return max_line_sine_; }
  // Forgets the recorded poses (the map frame moved).
  void forget_map_poses() {
    map_poses_.clear();
    two_anchor_priors_.clear();
    root_rotations_.clear();
  }
  // Gives a point its map position (and its place in the global index).
  void set_global(PointId id, const Eigen::Vector3d& g);
  // Retires a group (thesis 6.3.3: a group never changes; it is replaced): off its members'
  // refs and out of the counts.
  void retire(RltGroup& group);
  // Records that a point's map state changed this iteration (StepResult::changed).
  void mark_changed(PointId id);
  // The points marked this iteration, in marking order; the list starts empty again.
  std::vector<PointId> take_changed();

 private:
  // A group with exactly two anchors on the map: registered by them, the rotation about their
  // line from the recorded poses at iterations the group used (each pose composed with the
  // group's basis frame there), averaged over all of them since the group began (one
  // iteration's pose and basis frame carry a whole observation's noise, and the group's members
  // followed it from iteration to iteration). Nothing without such a pose.
  std::optional<Rigid3> register_on_two_anchors(const RltGroup& group);
  // Per two-anchor group: the sum of its prior rotations (world_R_group) and the latest map
  // pose's iteration already considered.
  struct TwoAnchorPrior {
    Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
    int count = 0;
    int last = -1;
  };
  std::unordered_map<GroupId, TwoAnchorPrior> two_anchor_priors_;
  // Deviation (adaptive preset, PointSlamOptions::root_rotation_window): a root group
  // registered to the map frame's observations with its rotation fitted over its first
  // iterations from the map frame on (rotation_fit.hpp), the translation putting its members'
  // centroid on their first observations. Nothing before three such iterations.
  std::optional<Rigid3> register_root(const RltGroup& group);
  // Per root group: its fitted rotation (world_R_group), settled once the group has used an
  // iteration past the window (its rotations there no longer change but for the averages'
  // refinement, and refitting every iteration would cost the window's registrations each time).
  struct RootRotation {
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    bool settled = false;
  };
  std::unordered_map<GroupId, RootRotation> root_rotations_;

  bool two_point_ = false;     // two_point_registration_on(options)
  double max_line_sine_ = 0;   // sine of two_point_max_elevation_deg
  int pose_window_ = 0;        // history_window(options)
  int root_window_ = 0;        // root_rotation_window_on(options)
  std::deque<std::pair<int, Rigid3>> map_poses_;  // (iteration, world_T_robot), oldest first
  std::vector<PointId> changed_;
  std::vector<int> changed_at_;  // per point: the iteration it was last marked
};

}  // namespace relslam::point
