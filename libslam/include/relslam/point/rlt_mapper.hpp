#pragma once
// RltMapper (thesis 6.4.3): the Relative Point SLAM algorithm, one iteration at a time.
// Eigen only: no I/O, MRPT or JSON. Truth never enters.

#include "relslam/core/observation.hpp"
#include "relslam/core/rigid.hpp"
#include "relslam/point/group_creation.hpp"
#include "relslam/point/group_relaxation.hpp"
#include "relslam/point/options.hpp"
#include "relslam/point/point_matching.hpp"
#include "relslam/point/rlt_group.hpp"
#include "relslam/point/rlt_map.hpp"
#include "relslam/point/rlt_point.hpp"
#include "relslam/point/rlt_point_merging.hpp"
#include "relslam/point/turn_rate.hpp"

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace relslam::point {

enum class PoseSource : unsigned char {
  Start,              // the first iteration: the identity by definition (the map frame)
  MappedPoints,       // RltICP of this iteration's observations to their map positions (thesis 6.1)
  UnmappedPoints,     // fewer than 3 mapped points visible: registered to provisional positions
  TwoPoints,          // exactly 2 mapped points visible: registered to them, the rotation about their line
                      // from the latest map-registered pose (adaptive two_point_registration)
  OnePoint,           // one mapped point visible, no registration to provisional positions: the rotation of
                      // the latest map-registered pose, the translation from that point (adaptive)
  TwoUnmappedPoints,  // two points with a map or provisional position visible, not both mapped: as TwoPoints,
                      // the rotation about their line from the latest pose (adaptive average_provisional)
  OneUnmappedPoint,  // one provisional point visible (or two on a steep line), no mapped one: as OnePoint, the rotation
                     // of the latest pose (adaptive average_provisional)
  Held,              // no registration possible: the previous pose is kept
  Odometry,          // use_odometry, no registration to three or more points: the previous pose moved by
                     // the frame's odometry
};

// The pose's position and rotation came from the map itself (the map frame or mapped points).
constexpr bool from_map(PoseSource s) {
  return s == PoseSource::Start || s == PoseSource::MappedPoints || s == PoseSource::TwoPoints;
}
// A registration fixed the pose's rotation (it measures the turn rate, TurnRate).
constexpr bool rotation_registered(PoseSource s) {
  return from_map(s) || s == PoseSource::UnmappedPoints || s == PoseSource::TwoUnmappedPoints;
}

// Wall time of the thesis's components (Figs 138–142), milliseconds.
struct StepTimings {
  double init_ms = 0;     // local candidates and the local OVLPQuadTree
  double load_ms = 0;     // matching observations, creating RltPoints
  double compute_ms = 0;  // group averages and RltICP anchoring
  double merge_ms = 0;    // RltPoint merging (thesis 6.5.2), including the groups it recomputes
  double create_ms = 0;   // group creation (and clean-up), binning included
  double binning_ms = 0;  // of which dynamic-point detection (thesis 6.5.3, Fig 117)
  double pose_ms = 0;     // current position
  double relax_ms = 0;    // global relaxation (beyond the thesis): building, solving, applying
  double total_ms() const { return init_ms + load_ms + compute_ms + merge_ms + create_ms + relax_ms + pose_ms; }
};

struct StepResult {
  int iteration = 0;
  Rigid3 world_T_robot;
  PoseSource pose_source = PoseSource::Start;
  std::vector<PointId> assignment;  // RltPoint of each observation, in input order
  std::vector<PointId> changed;     // RltPoints whose map position was set or moved this iteration
  int new_points = 0;
  int local_matches = 0;
  int global_matches = 0;
  int groups_created = 0;
  int dynamic_flagged = 0;  // points RltBinning flagged this iteration
  int merges = 0;           // RltPoints merged into older ones this iteration
  int binning_comparisons = 0;
  bool relaxed = false;             // a global relaxation ran this iteration (beyond the thesis)
  bool relaxation_skipped = false;  // one was due but no tie's gap triggered it (relaxation_trigger_gap)
  RelaxationReport relaxation;      // its outcome, when relaxed
  StepTimings timings;
};

// Sequences one iteration (thesis 6.4.3): matching, merging (rlt_point_merging.hpp), group
// computation, group creation (group_creation.hpp) and the current pose, all on one RltMap.
class RltMapper {
 public:
  // logic_error if check(options) finds a problem: callers validate user input first.
  // A global_relaxation other than off needs `relaxer` (relax::solve_relaxation): logic_error
  // without one.
  explicit RltMapper(const PointSlamOptions& options = {}, GroupRelaxer relaxer = {});

  // One iteration (thesis 6.2–6.5 as ordered in thesis 6.4.3). Iterations must increase; points
  // are robot-frame observations in any order. The first frame defines the world frame.
  StepResult step(const ObservationFrame& frame);
  // The same with some matches forced (observation index -> RltPoint id) over what matching
  // found: how a test plants a deliberately wrong global match in a whole run.
  StepResult step(const ObservationFrame& frame, const std::vector<std::pair<int, PointId>>& forced_matches);

  RltMapper(RltMapper&&) noexcept;
  ~RltMapper();

  const std::vector<RltPoint>& points() const { return map_.points; }
  const std::vector<RltGroup>& groups() const { return map_.groups; }
  const Rigid3& pose() const { return pose_; }
  GroupStats group_stats() const { return map_.stats; }
  // The iteration whose robot frame is the map frame: the first, or with the adaptive preset a
  // later one when the first could not root the map.
  int first_iteration() const { return map_.first_iteration; }
  // Empty while the run is healthy; otherwise why no map can ever be built.
  const std::string& failure() const { return failure_; }
  const PointSlamOptions& options() const { return options_; }

 private:
  void build_local_index(int k, const std::optional<Rigid3>& odometry);
  LocalCandidate local_candidate(const RltPoint& p, int k) const;
  void record(PointId id, const Eigen::Vector3d& p, int k, bool returned);
  PointId create_point(const Eigen::Vector3d& p, int k);
  void compute_groups(int k);
  void check_map_frame(int k);
  void move_map_frame(int k);
  // [load] The frame's observations to their RltPoints, matched or new; true when one re-found a
  // point unseen for relaxation_loop_gap iterations (a loop closure).
  bool load(const ObservationFrame& frame, const std::vector<std::pair<int, PointId>>& forced_matches,
            StepResult& result);
  // [relax] When global relaxation runs (beyond the thesis).
  void schedule_relaxation(int k, bool loop_closed, StepResult& result);

  // [pose] Current position (thesis 6.1): the prediction, the registration to mapped points,
  // then the first of the pose cases (locate) that gives a pose.
  void update_pose(const ObservationFrame& frame, StepResult& result);
  // Where the robot should be before registering: dead-reckoned (use_odometry) and its rotation,
  // or the latest rotation turned on at the measured rate.
  struct PosePrediction {
    std::optional<Rigid3> dead_reckoned;
    Eigen::Matrix3d rotation;
  };
  PosePrediction predict_pose(const ObservationFrame& frame) const;
  // The first (up to) two pairs with a mapped point (the adaptive preset's one- and two-point poses).
  struct MappedPairs {
    std::size_t count = 0;
    std::array<Eigen::Vector3d, 2> robot, world;
  };
  // The seen points' observations registered to their global (and with `provisional` their
  // provisional) positions, the pairs left in robot_scratch_/world_scratch_; an implausible
  // registration is dropped and sets `rejected`.
  std::optional<Rigid3> register_seen(const std::vector<PointId>& seen, bool provisional,
                                      const PosePrediction& prediction, bool& rejected);
  // What the pose cases of one iteration share: the points seen, the prediction, the
  // registration to mapped points and its first pairs, and whether a registration was rejected
  // as implausible (the cases that register again may set it).
  struct PoseAttempt {
    int k;
    const std::vector<PointId>& seen;
    PosePrediction prediction;
    std::optional<Rigid3> mapped_registration;  // register_seen(seen, false)
    MappedPairs mapped;
    bool rejected = false;
  };
  // The pose cases, one per PoseSource but Held, each the pose it gives or nothing; locate tries
  // them in their table's order (rlt_mapper.cpp), sets pose_ from the first that gives one and
  // says which (Held when none does).
  PoseSource locate(PoseAttempt& a);
  std::optional<Rigid3> at_map_frame(PoseAttempt& a);
  std::optional<Rigid3> by_mapped_points(PoseAttempt& a);
  std::optional<Rigid3> by_two_mapped_points(PoseAttempt& a);
  std::optional<Rigid3> by_unmapped_points(PoseAttempt& a);
  std::optional<Rigid3> by_odometry(PoseAttempt& a);
  std::optional<Rigid3> by_two_unmapped_points(PoseAttempt& a);
  std::optional<Rigid3> by_one_mapped_point(PoseAttempt& a);
  std::optional<Rigid3> by_unmapped_centroid(PoseAttempt& a);
  // provisional_rotation_weight's pose: part of `registered`'s rotation, the position from the
  // scratch pairs' centroid.
  Rigid3 weigh_provisional(const Rigid3& registered, const Eigen::Matrix3d& predicted) const;
  // Provisional positions of the unmapped points seen now (Deviation, see options).
  void place_provisional(const std::vector<PointId>& seen);
  // A registration strays from the dead-reckoned pose by more than odometry_max_turn_deg or
  // odometry_max_shift (use_odometry), or else its rotation differs from the predicted one by
  // more than max_turn_deg (adaptive preset only).
  bool implausible(const Rigid3& registered, const Eigen::Matrix3d& predicted,
                   const std::optional<Rigid3>& dead_reckoned) const;
  void relax(StepResult& result);

  PointSlamOptions options_;
  RltMap map_;
  PointMatcher matcher_;
  GroupCreation creation_;
  RltPointMerging merging_;
  Rigid3 pose_;
  bool pose_from_map_ = false;  // pose_ was registered to mapped points (or is the map frame)
  int pose_iteration_ = kNone;  // the iteration pose_ is of
  TurnRate turn_rate_;          // measured on the poses whose rotation was registered (adaptive)
  int rejected_turns_ = 0;      // iterations in a row whose registration max_turn_deg rejected
  std::string failure_;
  GroupRelaxer relaxer_;
  int relax_at_ = kNone;           // iteration of the solve a loop closure scheduled
  int next_relax_ = kNone;         // the earliest iteration the next loop-closure solve may run
  std::vector<PointId> held_off_;  // points with a tie over relaxation_trigger_gap after the last solve, sorted

  // Per-iteration scratch.
  std::vector<PointId> scratch_ids_;
  std::vector<LocalCandidate> local_candidates_;
  std::vector<GroupId> queued_groups_;  // groups notified this iteration (thesis 6.3.3)
  std::vector<int> group_queued_at_;
  std::vector<Eigen::Vector3d> robot_scratch_, world_scratch_;  // update_pose's registration pairs
};

}  // namespace relslam::point
