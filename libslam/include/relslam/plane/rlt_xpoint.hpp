#pragma once
// RltXPoint (thesis 4.3.2, 4.4.3.2): a group of RltPlanes seen together and
// their relative map, chained from pairwise comparisons.

#include "relslam/core/planar_pose.hpp"
#include "relslam/plane/ids.hpp"
#include "relslam/plane/key_point_compare.hpp"
#include "relslam/plane/options.hpp"
#include "relslam/plane/pair_comparison.hpp"
#include "relslam/plane/rlt_plane.hpp"
#include "relslam/plane/rlt_plane_compare.hpp"
#include "relslam/plane/rlt_plane_interval.hpp"

#include <optional>
#include <vector>

namespace relslam::plane {

// Rule 35's copy of an RltXPoint's best complete result (thesis 4.3.7.3), for the chain it was
// computed on. At namespace scope, not nested in RltXPoint: clang cannot default-construct a
// nested struct with default member initialisers (optional::emplace) while the enclosing class
// is incomplete, which GCC accepts.
struct RltXPointSnapshot {
  std::vector<PlaneId> chain;
  std::vector<RltXPointRef> refs;  // by chain position
  std::vector<CompareResult> edges;
  double total_length = 0;
  long long total_samples = 0;
};

// Invariant: every plane of the chain lists this group among its refs exactly once, and the
// chain holds each plane once. The relative map lives in those refs: the base (first) plane's
// reference point is the group's origin.
// What ComputeXPoint reads of RelativePlaneOptions (thesis 4.4.3.2, 4.3.6). Converts from the
// whole options, so a caller holding them passes them as they are.
struct ComputeXPointOptions {
  ComparePlanesOptions compare;  // each edge's ComparePlanes (Rules 13–15, 18, 19)
  IntervalMode interval_mode;    // the iterations comparisons are limited to
  bool key_points;               // part 2: key points and size correction
  double same_length;            // lengths and offsets equal within it (Rules 28, 35, 36)
  bool missing_key_points;       // Rule 19
  bool size_correction;          // Rule 28
  bool save_snapshot;            // Rule 35
  bool save_reserve;             // Rule 36
  // Adaptive preset: a plane chained between two edges that anchored it on different ends, never
  // seen whole, breaks the chain there (RltXPoint::chain_with_size_correction) [C].
  bool consistent_ends;
  ComputeXPointOptions() : ComputeXPointOptions(RelativePlaneOptions{}) {}  // the defaults of RelativePlaneOptions
  ComputeXPointOptions(const RelativePlaneOptions& o)                       // NOLINT(google-explicit-constructor)
      : compare(o),
        interval_mode(o.interval_mode),
        key_points(o.key_points),
        same_length(o.same_length),
        missing_key_points(o.rules.missing_key_points),
        size_correction(o.rules.size_correction),
        save_snapshot(o.rules.save_snapshot),
        save_reserve(o.rules.save_reserve),
        consistent_ends(map_grounded(o)) {}
};

// What ReorderPlanes reads of RelativePlaneOptions (Rule 30, thesis 4.3.7.1): when it is due,
// and the pairwise comparisons it orders the planes by.
struct ReorderPlanesOptions {
  ComparePlanesOptions compare;
  IntervalMode interval_mode;
  bool reorder_planes;         // rules.reorder_planes: periodically
  bool reorder_broken_chains;  // rules.reorder_broken_chains: while unplaced
  ReorderOptions reorder;
  // grounded_map with open_cut_ends: a group whose chain broke at a plane anchored on different ends
  // (ComputeXPointOptions::consistent_ends) is searched again, at most every reorder.broken_gap
  // iterations, for an order through consistent ends (consistent_chain.hpp) [C].
  bool consistent_ends;
  double same_length;  // a plane seen whole: its longest uncut reading within this of its longest
  ReorderPlanesOptions() : ReorderPlanesOptions(RelativePlaneOptions{}) {}  // the defaults of RelativePlaneOptions
  ReorderPlanesOptions(const RelativePlaneOptions& o)                       // NOLINT(google-explicit-constructor)
      : compare(o),
        interval_mode(o.interval_mode),
        reorder_planes(o.rules.reorder_planes),
        reorder_broken_chains(o.rules.reorder_broken_chains),
        reorder(o.reorder),
        consistent_ends(chains_through_consistent_ends(o)),
        same_length(o.same_length) {}
};

class RltXPoint {
 public:
  RltXPoint(XPointId id, int created_iteration, std::vector<PlaneId> chain);

  XPointId id() const { return id_; }
  int created_iteration() const { return created_iteration_; }
  // The comparison chain: planes[i−1] is compared with planes[i]; planes[0] is the base.
  // First in RltPlane creation order (the order the sensor reported them).
  const std::vector<PlaneId>& planes() const { return chain_; }
  // Groups linked to this one either way (EnumXPConection).
  const std::vector<XPointId>& adjacent() const { return adjacent_; }
  // The last comparison of each chain edge: edges()[i] compares planes[i] with planes[i+1].
  const std::vector<CompareResult>& edges() const { return edges_; }

  // Rule 7 (CanAdd, thesis 4.3.2): `candidate` was seen together with every plane of the group
  // for at least `min_common` iterations.
  bool can_add(const std::vector<RltPlane>& planes, const RltPlane& candidate, int min_common) const;
  // GetMinimumInterval over all planes: the iterations in which every plane was seen.
  void common_interval(const std::vector<RltPlane>& planes, RltPlaneInterval& out) const;

  // Appends `plane` to the chain and gives it its membership.
  void add_plane(std::vector<RltPlane>& planes, PlaneId plane, int iteration);
  void add_adjacent(XPointId other) { adjacent_.push_back(other); }
  // A new comparison order over the same planes (the hook of Rule 30's ReorderPlanes; Rule 2
  // says a noise-free map does not depend on it). logic_error if the planes differ.
  void set_chain(std::vector<PlaneId> order);

  // ComputeXPoint (thesis 4.4.3.2): compares each chain edge and composes the results into every
  // plane's pose in the group frame (SE(2) composition: the thesis's "add the running offset",
  // Rules 2, 6). A plane after an edge with no common iteration is marked invalid. With
  // options.key_points (part 2) each edge is compared by key points (Rules 13–15, 18) and the
  // chain is composed with size correction (Rule 28, thesis 4.3.6).
  void compute(std::vector<RltPlane>& planes, const ComputeXPointOptions& options);

  // ReorderPlanes (Rule 30, thesis 4.3.7.1) when it is due at `iteration`: periodically with
  // options.reorder_planes (options.reorder), and with rules.reorder_broken_chains while
  // the group is not placed and an edge of its chain could not place both its planes (then only
  // a chain whose edges all can replaces it). The chain becomes the best path by the planes' pairwise comparison
  // intervals with valid key points (reorder_planes.hpp). True when the chain changed (the group is then recomputed);
  // the Rule 36 reserves of the edges that changed are then cleared.
  bool reorder_if_due(std::vector<RltPlane>& planes, const ReorderPlanesOptions& options, int iteration);

  // CheckIntervalSize (Rules 31, 32; thesis 4.3.7.2), after compute(): a plane's membership is
  // confirmed once the comparison placing it — the chain edge from the plane before it — averaged
  // options.min_interval iterations; a plane still unconfirmed options.confirm_after iterations
  // after it joined is appended to `failed` (the caller sends a hint back and rolls back, Rule
  // 34). The base plane is the group's origin and placed by no comparison.
  void check_interval_size(std::vector<RltPlane>& planes, const RollBackOptions& options, int iteration,
                           std::vector<PlaneId>& failed) const;

  // Frees the observations compute() copies out for its comparisons (refilled by every compute):
  // a checkpoint of the state (Rule 33) need not keep them.
  void release_scratch();

  // Set when one of the planes got an observation or the chain changed: the group is then
  // recomputed; groups that saw nothing new cost nothing (thesis 4.2.2).
  bool needs_compute() const { return needs_compute_; }
  void mark_changed() { needs_compute_ = true; }

  // A motion-model group (RltXMMPoint, thesis 4.3.6): its frame is fixed at the last valid pose
  // (Rule 27), it never takes a plane (thesis 4.3.2) and its RltXMMPoint computes it.
  bool motion_model() const { return anchor_.has_value(); }
  const std::optional<PlanarPose>& anchor() const { return anchor_; }
  void set_anchor(const PlanarPose& world_T_xpoint) { anchor_ = world_T_xpoint; }
  // Adaptive preset: the motion model's track started from a checked pose and measured every
  // step's motion along its plane (RltXMMPoint::along_observed), so the groups linked from it are
  // placed by what was observed (MapPlane::grounded).
  bool track_trusted() const { return track_trusted_; }
  void set_track_trusted(bool trusted) { track_trusted_ = trusted; }

  // Placed by RltMapBuilder::build_map: world_T_xpoint.
  const PlanarPose& world_pose() const { return world_pose_; }
  bool placed() const { return placed_; }
  void place(const PlanarPose& world_T_xpoint, bool placed) {
    world_pose_ = world_T_xpoint;
    placed_ = placed;
  }

 private:
  XPointId id_;
  int created_iteration_;
  std::vector<PlaneId> chain_;
  std::vector<XPointId> adjacent_;
  std::vector<CompareResult> edges_;
  bool needs_compute_ = true;
  int last_reorder_ = -1;  // iteration of the last Rule 30 search, -1: none yet
  PlanarPose world_pose_;
  bool placed_ = false;
  std::optional<PlanarPose> anchor_;
  bool track_trusted_ = false;
  void compute_with_key_points(std::vector<RltPlane>& planes, const ComputeXPointOptions& options,
                               const RltPlaneInterval* within);
  // reorder_if_due's two ends: grounded_map's search through consistent ends, and the new order
  // (chain positions) made the chain, the Rule 36 reserves of the edges that changed cleared.
  bool reorder_consistently(std::vector<RltPlane>& planes, const std::vector<std::vector<int>>& weight,
                            const std::vector<std::vector<KeyPoint>>& end, const std::vector<int>& current,
                            const ReorderPlanesOptions& options);
  void use_order(std::vector<RltPlane>& planes, const std::vector<int>& path);
  // compute_with_key_points's three parts (thesis 4.3.6): edge comparison (ComparePlanes with key
  // points, Rules 13–15, 18, 36), canonical sizes (each plane's largest length and its key point,
  // Rule 19 for a missing one), and chaining with size correction (Rules 2, 6, 15, 28).
  struct Canonical;
  void compare_edges(std::vector<RltPlane>& planes, const ComputeXPointOptions& options,
                     const RltPlaneInterval* within);
  std::vector<Canonical> canonical_sizes(const std::vector<RltPlane>& planes, const ComputeXPointOptions& options,
                                         const RltPlaneInterval* within);
  void chain_with_size_correction(std::vector<RltPlane>& planes, const ComputeXPointOptions& options,
                                  const RltPlaneInterval* within, const std::vector<Canonical>& canonical);
  // Rule 19: chain plane k's key point in the growth phase holding `iteration`, KeyPoint::None
  // when the other planes cannot tell (or Rule 19 is off).
  KeyPoint key_point_in(const std::vector<RltPlane>& planes, const ComputeXPointOptions& options,
                        const RltPlaneInterval* within, std::size_t k, int iteration);

  RltPlaneInterval scratch_common_;  // reused by compute() in IntervalMode::Group
  // The iterations comparisons are limited to: the group's common interval in
  // IntervalMode::Group (kept in scratch_common_), nullptr (all) in IntervalMode::Pair.
  const RltPlaneInterval* comparison_window(const std::vector<RltPlane>& planes, IntervalMode mode);
  // Per chain plane, part 2 in IntervalMode::Group: its observations inside the group's
  // common interval, filled on demand.
  std::vector<std::vector<PlaneObject>> scratch_observations_;
  std::vector<char> observations_filled_;

  // Each chain edge's comparison, kept up to date as its planes are seen (part 2): a group with
  // one plane in view recomputes only the edges that got a common sample, and those only over
  // what changed (thesis 4.2.2, 4.3.8: time follows the planes in view).
  std::vector<PairComparison> pair_comparisons_;

  // Rule 35's copy of the best complete result (thesis 4.3.7.3), for the chain it was computed on.
  std::optional<RltXPointSnapshot> snapshot_;
  void keep_or_restore_snapshot(std::vector<RltPlane>& planes, double same_length);
  // Chain plane k's observations: where they are stored, or only those inside `within`.
  ObservationView observations(const std::vector<RltPlane>& planes, std::size_t k, const RltPlaneInterval* within);
};

}  // namespace relslam::plane
