#pragma once
// Point matching (thesis 6.2.5, 6.5.1): each observation goes to an RltPoint seen in the last
// few iterations (local, untransformed), else to one on the map near where the current pose
// puts it (global), else it starts a new RltPoint.

#include "relslam/core/rigid.hpp"
#include "relslam/point/options.hpp"
#include "relslam/point/rlt_point.hpp"
#include "relslam/spatial/global_index.hpp"
#include "relslam/spatial/local_index.hpp"

#include <deque>
#include <memory>
#include <vector>

namespace relslam::point {

// A point seen in the last few iterations: its latest untransformed observation.
struct LocalCandidate {
  PointId id = kNone;
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  int iteration = 0;
};

struct MatchResult {
  std::vector<PointId> assigned;  // per observation; kNone: a new RltPoint
  int local = 0;
  int global = 0;
  // robot_k_T_robot_{k-1}: the frame-to-frame motion the local matches imply (identity when
  // fewer than 3 matches); used to predict the next iteration and the pose for global matching.
  Rigid3 motion;
  bool motion_estimated = false;
};

// Keeps scratch space and the recent frame-to-frame motions between iterations.
// One-to-one within an iteration: candidate pairs are taken closest first, ties by
// observation then id order, so the result never depends on hash or memory order.
class PointMatcher {
 public:
  explicit PointMatcher(const PointSlamOptions& options);

  // Stage 1 (the thesis's "init"): the local index over the candidates, each predicted
  // into the current frame (see PointSlamOptions::compensate_motion). `odometry`, when given,
  // is this frame's measured motion (previous_T_current): it predicts the last step.
  void prepare(const std::vector<LocalCandidate>& candidates, int k, const std::optional<Rigid3>& odometry = {});
  // Stage 2 ("load"): local matches, then global ones through world_T_previous composed with
  // the motion found locally.
  const MatchResult& match(const std::vector<Eigen::Vector3d>& observations, int k, spatial::GlobalIndex& global,
                           const std::vector<RltPoint>& points, const Rigid3& world_T_previous);

 private:
  struct Pair {
    double distance;
    int observation;
    PointId id;
  };
  Rigid3 predicted_motion(int from, int to) const;  // robot_to_T_robot_from from stored motions
  // With candidates_T_built, the candidates have moved by it since the local index was built.
  void match_local(const std::vector<Eigen::Vector3d>& observations, double bound,
                   const Rigid3* candidates_T_built = nullptr);
  // The same pass over the pairs the first, unmoved pass found (first_pairs_).
  void rematch_local(const std::vector<Eigen::Vector3d>& observations, double bound);
  void begin_local_pass(std::size_t observations);
  // Pairs observation i with candidate id, found at `candidate`, if within bound.
  void add_pair(const Eigen::Vector3d& observation, int i, PointId id, const Eigen::Vector3d& candidate, double bound);
  std::optional<Rigid3> robust_motion(const std::vector<Eigen::Vector3d>& observations);
  void assign_greedily(int& counter);
  void take(const Pair& pair, int& counter);  // assigns the pair unless either side is taken
  bool taken(PointId id) const { return id < static_cast<PointId>(taken_.size()) && taken_[id] == stamp_; }

  PointSlamOptions options_;
  std::unique_ptr<spatial::LocalIndex> local_;
  std::vector<spatial::IndexedPoint> predicted_;  // candidates moved into the current frame
  std::vector<int> slot_;                         // per point id: its index in predicted_
  std::deque<std::pair<int, Rigid3>> motions_;    // (k, robot_k_T_robot_{k-1}), recent first
  std::optional<Rigid3> measured_step_;           // this frame's odometry as robot_k_T_robot_{k-1}
  int current_ = 0;                               // the iteration being matched
  MatchResult result_;
  std::vector<Pair> pairs_;
  std::vector<Pair> first_pairs_;  // the first local pass's pairs, before assignment
  std::vector<unsigned> taken_;  // per point: the stamp of the iteration that took it
  std::vector<Eigen::Vector3d> from_, to_;  // robust_motion's pairs
  std::vector<double> residuals_, sorted_residuals_;
  std::vector<int> claims_;      // per point: pairs naming it in the batch being assigned (else 0)
  std::vector<std::optional<Rigid3>> motion_from_;  // prepare(): prediction from k - index
  unsigned stamp_ = 0;
};

// Global matching position of an RltPoint: its map position, or (when allowed) its
// provisional one; nothing for points that must not be matched globally.
const Eigen::Vector3d* global_match_position(const RltPoint& p, bool match_unmapped);

}  // namespace relslam::point
