#pragma once
// RltXPointsS (thesis 4.4.3.1, 4.5; spec §5.4, §5.5, §5.13): the Relative Plane algorithm's
// entry class, one call per iteration. Eigen only: no I/O, JSON or simulator; truth never
// enters.

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"
#include "relslam/plane/ids.hpp"
#include "relslam/plane/options.hpp"
#include "relslam/plane/rlt_map_builder.hpp"
#include "relslam/plane/rlt_plane.hpp"
#include "relslam/plane/rlt_plane_interval.hpp"
#include "relslam/plane/rlt_xpoint.hpp"
#include "relslam/plane/rlt_xpoint_link.hpp"
#include "relslam/plane/rlt_xmm_point.hpp"

#include <span>
#include <utility>
#include <vector>

namespace relslam::plane {

// Wall time of the thesis's parts of one iteration (the Profiler of 4.4.2.5), milliseconds.
struct PlaneStepTimings {
  double add_ms = 0;      // AddPlane: registration (Rules 1, 10, 11)
  double manage_ms = 0;   // ManageXPoints: grouping and linking (Rules 7–9, 12)
  double compute_ms = 0;  // ComputeXPoints: pairwise comparisons and chaining (Rules 2, 3, 6)
  double build_ms = 0;    // BuildMap (Rules 4, 6, 8)
  double pose_ms = 0;     // GetPoset (Rule 5)
  double total_ms() const { return add_ms + manage_ms + compute_ms + build_ms + pose_ms; }
};

// What one iteration produced. The spans point into the algorithm and stay valid until the
// next step() (no copy per iteration).
struct RelativePlaneStep {
  int iteration = 0;
  PlanarPose world_T_robot;  // meaningful only when pose_valid
  bool pose_valid = false;
  int pose_planes = 0;                  // observations the pose came from
  std::span<const PlaneId> assignment;  // the RltPlane of each observation, in input order
  std::span<const MapPlane> map;        // one entry per RltPlane (MapPlane::mapped says if placed)
  std::span<const RltXPoint> groups;
  std::span<const RltXPointLink> links;
  XPointId current_group = kNone;
  int new_planes = 0;      // RltPlanes created
  int local_matches = 0;   // observations registered against a previous observation (Rule 1)
  int global_matches = 0;  // ... through the map and the previous pose (Rule 11)
  int groups_created = 0;
  int planes_grouped = 0;  // unassigned planes that joined or started a group
  int groups_computed = 0;
  int oneway_links = 0;  // Rule 37's one-way links added
  // The motion model carrying the pose this iteration (Rules 23–27), or nullptr.
  const RltXMMPoint* motion_model = nullptr;
  PlaneStepTimings timings;
};

// Invariant: planes() and xpoints() are indexed by their ids; each RltPlane is in the
// unassigned list or in at least one group, or was dropped from the list (then never mapped).
class RltXPointsS {
 public:
  // world_T_start: the robot pose of the first frame, the map's anchor (Rule 4: "(0,0) or some
  // other inputted coordinate"). logic_error if check(options) finds a problem.
  explicit RltXPointsS(const RelativePlaneOptions& options = {}, const PlanarPose& world_T_start = {});

  // One iteration (spec §5.13): StartIteration, AddPlane for each observation, ManageXPoints,
  // ComputeXPoints, BuildMap, GetPoset. Iterations must increase; planes in the robot frame.
  RelativePlaneStep step(const PlaneFrame& frame);

  const std::vector<RltPlane>& planes() const { return planes_; }
  const std::vector<RltXPoint>& xpoints() const { return xpoints_; }
  const std::vector<RltXPointLink>& links() const { return links_; }
  const std::vector<MapPlane>& map() const { return builder_.map(); }
  const std::vector<PlaneId>& unassigned() const { return unassigned_; }
  const RltPoset& pose() const { return pose_; }
  XPointId current_xpoint() const { return current_; }
  // Every motion model ever started, in order; the active one, if any, is last.
  const std::vector<RltXMMPoint>& motion_models() const { return motion_models_; }
  const RltXMMPoint* active_motion_model() const {
    return motion_model_active_ ? &motion_models_.back() : nullptr;
  }
  const RelativePlaneOptions& options() const { return options_; }

 private:
  void start_iteration(int iteration);
  void add_planes(const PlaneFrame& frame, RelativePlaneStep& result);
  PlanarPose pose_for_global_matching();
  void register_matches(int& counter, std::vector<PlaneId>* registered = nullptr);
  void add_to_plane(PlaneId plane, const PlaneObject& observation);
  PlaneId create_plane(const PlaneObject& observation);
  void manage_xpoints(RelativePlaneStep& result);
  bool bootstrap(RelativePlaneStep& result);
  bool join_group(PlaneId plane);
  bool make_new_xpoint(PlaneId plane, RelativePlaneStep& result);
  bool link_to_new_xpoint(XPointId from, PlaneId plane, std::vector<PlaneId>& linking);
  XPointId create_xpoint(std::vector<PlaneId> chain, XPointId from, std::vector<PlaneId> linking);
  void upkeep_unassigned();
  void regroup_reacquired(RelativePlaneStep& result);
  void chart_current_group();
  void set_current(XPointId x);
  bool switch_to_group_holding_all();
  int mend_merge_after_loop_closing(const PlanarPose& world_T_robot);
  void check_for_motion_model();
  void create_motion_model(PlaneId plane);
  void compute_xpoints(RelativePlaneStep& result);
  void get_poset();

  RelativePlaneOptions options_;
  PlanarPose world_T_start_;
  std::vector<RltPlane> planes_;
  std::vector<RltXPoint> xpoints_;
  std::vector<RltXPointLink> links_;
  std::vector<PlaneId> unassigned_;  // RltPlaneList, creation order
  // Rule 21: planes global matching re-acquired, with the iteration, until they are grouped.
  std::vector<std::pair<PlaneId, int>> reacquired_;
  std::vector<PlaneId> recent_;      // RltPlanes seen within local_match.max_iteration_gap
  std::vector<char> in_recent_;      // per RltPlane: in recent_
  RltMapBuilder builder_;
  RltPoset pose_;
  RltPoset last_valid_pose_;  // Rule 11 places observations with it [R, spec §5.9]
  int last_valid_iteration_ = 0;
  std::vector<RltXMMPoint> motion_models_;
  bool motion_model_active_ = false;  // the last of motion_models_ carries the pose
  int no_pose_count_ = 0;             // Rule 26: iterations without a pose ...
  int no_pose_start_ = 0;             // ... since this one
  XPointId current_ = kNone;  // the current group; the working group while managing
  int iteration_ = 0;
  bool started_ = false;

  // Per-iteration scratch, kept to avoid allocations.
  std::vector<PlaneObject> stamped_;  // the frame's planes with their iteration set
  std::vector<PlaneId> assignment_;
  std::vector<char> taken_;  // per RltPlane: registered this iteration
  std::vector<PlaneMatch> matches_;
  std::vector<PlaneId> reacquired_now_;  // Rule 11 this iteration
  std::vector<int> chart_;               // Rule 22: planes in view per group
  std::vector<RegisteredObservation> registered_;
  std::vector<char> visited_;
  std::vector<XPointId> stack_;
  std::vector<PlaneId> candidates_;
  RltPlaneInterval scratch_interval_;
};

}  // namespace relslam::plane
