#pragma once
// RltMapBuilder (thesis 4.4.3.11): the global map from the
// groups and their links, the current pose from this iteration's observations, and matching an
// observation against the map.

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"
#include "relslam/plane/ids.hpp"
#include "relslam/plane/key_point_compare.hpp"
#include "relslam/plane/line_placement.hpp"
#include "relslam/plane/options.hpp"
#include "relslam/plane/plane_object.hpp"
#include "relslam/plane/pose_integrity.hpp"
#include "relslam/plane/rlt_plane.hpp"
#include "relslam/plane/rlt_xpoint.hpp"
#include "relslam/plane/rlt_xpoint_link.hpp"

#include <optional>
#include <span>
#include <vector>

namespace relslam::plane {

class PoseMean;  // pose_mean.hpp, internal to libslam/plane

// Whether a plane placed at `length` anchored on `own` (None: no key point) has the wall's end k
// where it has its own end k: it is whole (seen static, or as long as the plane was ever seen,
// within same_length) or anchored on k itself. Used by MapPlane::holds_end and, in the adaptive
// preset, by Rule 17's links.
inline bool holds_end(bool size_static, KeyPoint own, double length, KeyPoint k, double longest_seen,
                      double same_length) {
  return size_static || own == KeyPoint::None || own == k || longest_seen <= length + same_length;
}

// One global-map entry per RltPlane (thesis 4.4.3.11).
struct MapPlane {
  bool mapped = false;
  PlaneObject plane;         // world frame, at `length`; plane.iteration is meaningless
  PlanarPose world_T_plane;  // the reference point and direction (plane.pose())
  double length = 0;
  XPointId source = kNone;  // the group that placed it
  KeyPoint key_point = KeyPoint::None;
  // The placing comparison saw the plane keep its size (RltXPointRef::size_static): both ends
  // are the wall's.
  bool size_static = false;
  // Beyond the thesis (adaptive preset): the group that placed it is reached from X0 by links
  // that never pass a motion-model group. A motion model's track takes its heading and its
  // offset from one plane and guesses the motion along it (Rules 23-25), so a group placed
  // through it carries that guess onto the map; a pose resting on such a plane agrees with it
  // because it was made from the same guess (pose_integrity.hpp).
  bool grounded = false;

  // Placed by a group, not by its line alone (place_by_lines, line_placement.hpp): only such an
  // entry is what the thesis's map holds, for the rules that ask whether a plane is placed
  // (Rules 19's extension, 26).
  bool group_placed() const { return mapped && source != kNone; }

  // Whether the entry's end k is a real end of the wall, so an observation grown from k (Rule 16)
  // may be put onto the entry. An entry shorter than the plane's longest observation (by more
  // than τ_len) is a piece: mapped at the largest size its group compared, it is right at its
  // key-point end only, and from the other end the pose would be off by the part its group never
  // saw (Map D, large frustum: wall 2 mapped at 3.95 of 4 by the one group it joined, seen whole
  // later, then cut at its other end). Any other entry is taken as whole.
  bool holds_end(KeyPoint k, double longest_seen, double same_length) const {
    return plane::holds_end(size_static, key_point, length, k, longest_seen, same_length);
  }
};

// RltPoset (thesis 4.4.3.18): a pose and whether it could be computed.
struct RltPoset {
  PlanarPose world_T_robot;
  bool valid = false;
  int planes_used = 0;  // observations that gave it (Rule 5)
  // Why it is (in)valid: the adaptive preset's check (pose_integrity.hpp); the thesis's GetPoset
  // leaves NoPlanes.
  PoseReason reason = PoseReason::NoPlanes;
};

// An observation of this iteration and the RltPlane it was registered to.
struct RegisteredObservation {
  const PlaneObject* observation = nullptr;
  PlaneId plane = kNone;
};

// A candidate registration, as MatchPlane scored it.
struct PlaneMatch {
  int observation = 0;  // index in the iteration's input
  PlaneId plane = kNone;
  double score = 0;
};

// What GetPoset reads of RelativePlaneOptions (Rules 5, 16, 19): a partial observation is grown
// from its key point (part 2), found by Rule 19's ComparePlanes when no membership has one.
// Converts from the whole options, so a caller holding them passes them as they are.
struct GetPosetOptions {
  ComparePlanesOptions compare;                                   // Rule 19's dummy references
  bool key_points;                                                // part 2
  bool missing_key_points;                                        // rules.missing_key_points (Rule 19)
  double same_length;                                             // an observation at the map's size
  GetPosetOptions() : GetPosetOptions(RelativePlaneOptions{}) {}  // the defaults of RelativePlaneOptions
  GetPosetOptions(const RelativePlaneOptions& o)                  // NOLINT(google-explicit-constructor)
      : compare(o),
        key_points(o.key_points),
        missing_key_points(o.rules.missing_key_points),
        same_length(o.same_length) {}
};

// What BuildMap reads of RelativePlaneOptions (Rules 4, 6, 8, 17): GetPoset's key points (Rule
// 4's first-reading resize finds them the same way) and Rule 4's two switches.
struct BuildMapOptions {
  GetPosetOptions key_point;
  bool anchor_first_observation;  // rules.anchor_first_observation (Rule 4)
  bool first_reading_resize;      // rules.first_reading_resize (Rule 4, thesis 4.4.3.11 step 1)
  // Adaptive preset: a grounded group's placement of a plane replaces one through a motion model
  // (MapPlane::grounded); the thesis keeps the first [T].
  bool prefer_grounded;
  // open_cut_ends in effect: X0 is put first by the planes whose first observation has an end the
  // sensor did not cut (RltMapBuilder::place_x0).
  bool cut_ends_open;
  // observed_anchor in effect: X0 only from uncut ends or two non-parallel lines (x0_anchor.hpp).
  bool observed_anchor;
  double min_angle_rad;  // integrity.min_angle_rad: two lines that fix a position
  // place_by_lines in effect: walls and unplaced groups placed by the walls' lines
  // (line_placement.hpp), held to the pose check's bounds.
  bool place_by_lines;
  LinePlacementOptions line;
  BuildMapOptions() : BuildMapOptions(RelativePlaneOptions{}) {}  // the defaults of RelativePlaneOptions
  BuildMapOptions(const RelativePlaneOptions& o)                  // NOLINT(google-explicit-constructor)
      : key_point(o),
        anchor_first_observation(o.rules.anchor_first_observation),
        first_reading_resize(o.rules.first_reading_resize),
        prefer_grounded(map_grounded(o)),
        cut_ends_open(plane::cut_ends_open(o)),
        observed_anchor(anchor_observed(o)),
        min_angle_rad(o.integrity.min_angle_rad),
        place_by_lines(lines_placed(o)),
        line{o.place_line_samples, o.integrity.offset_bound, o.integrity.angle_bound_rad, o.integrity.min_angle_rad} {}
};

class RltMapBuilder {
 public:
  // BuildMap (Rules 4, 6, 8): places every group by walking the links in creation order and
  // writes each plane of a placed group onto the map — the first group to place it wins, a
  // later one only with a larger size [T, A47]. X0 is put where its planes' first observations,
  // seen from world_T_start, say (Rule 4; options.rules.anchor_first_observation false leaves
  // it at the identity); every other group where its linking planes' two memberships agree,
  // averaged (Rule 8). With options.key_points a first observation smaller than the plane's
  // size in X0 is grown from its key point first (Rule 4's first-reading resize, thesis 4.4.3.11
  // step 1), and a linking plane's smaller membership is re-anchored to the larger (Rule 17).
  // With options.place_by_lines a group no link places is placed on its walls on the map, and
  // each wall `lines` placed that no group does goes onto the map as its line
  // (line_placement.hpp).
  void build_map(std::span<const RltXPointLink> links, std::vector<RltXPoint>& xpoints,
                 const std::vector<RltPlane>& planes, const PlanarPose& world_T_start, const BuildMapOptions& options,
                 std::span<const LinePlacement> lines = {});

  // GetPoset (Rule 5): the mean of CalculateOffset over the observations whose RltPlane is on
  // the map at the same size; recomputed from scratch each iteration, never carried forward.
  // With options.key_points a partial observation is grown to the map's size from its key point
  // at this iteration (Rule 16) — a membership's key point computed on a piece holding this
  // iteration, else one found by Rule 19 against the other observations of the iteration; an
  // observation with no static end gives no pose (thesis 4.4.3.11).
  RltPoset get_poset(std::span<const RegisteredObservation> observations, const std::vector<RltPlane>& planes,
                     const GetPosetOptions& options) const;

  // MatchPlanetoMap (Rule 11): every mapped plane not in `taken`, seen from world_T_robot,
  // scored against `observation` (robot frame); candidates go to `out` (the caller keeps the
  // best).
  void match_plane_to_map(int observation_index, const PlaneObject& observation, const PlanarPose& world_T_robot,
                          const MatchBounds& bounds, bool same_normal_direction, const std::vector<char>& taken,
                          std::vector<PlaneMatch>& out) const;

  const std::vector<MapPlane>& map() const { return map_; }
  int mapped_count() const { return mapped_count_; }

 private:
  // Rule 8 (with Rule 17): where `link` puts its group, added to world_T_to.
  void link_to(const RltXPointLink& link, const std::vector<RltXPoint>& xpoints, const std::vector<RltPlane>& planes,
               const BuildMapOptions& options, PoseMean& world_T_to) const;
  // The group a link from `from` through plane p is placed from (MapPlane::grounded).
  XPointId link_source(const RltXPoint& from, PlaneId p, const BuildMapOptions& options) const;
  // place_by_lines: where `to`'s planes lie on their walls on the map (or in `lines`), added to
  // world_T_to.
  void place_on_walls(const RltXPoint& to, const std::vector<RltPlane>& planes, std::span<const LinePlacement> lines,
                      const BuildMapOptions& options, PoseMean& world_T_to) const;
  // place_by_lines: the walls of `lines` no group placed, onto the map.
  void place_lines(std::span<const LinePlacement> lines);
  void place_planes(const RltXPoint& xpoint, const std::vector<RltPlane>& planes, bool grounded,
                    const BuildMapOptions& options);
  // Rule 4: where X0 is, from its planes' first observations, added to world_T_x0 (none: unplaced).
  void place_x0(const RltXPoint& x0, const std::vector<RltPlane>& planes, const PlanarPose& world_T_start,
                const BuildMapOptions& options, PoseMean& world_T_x0) const;
  static std::optional<PlanarPose> lines_first_observation_pose(const RltXPoint& x0, const std::vector<RltPlane>& planes,
                                                                int earliest, const PlanarPose& world_T_start,
                                                                const BuildMapOptions& options);
  std::optional<PlanarPose> uncut_first_observation_pose(const RltXPoint& x0, const RltPlane& plane,
                                                         const BuildMapOptions& options) const;
  std::optional<PlanarPose> first_observation_pose(const RltXPoint& x0, const RltPlane& plane,
                                                   const std::vector<RltPlane>& planes,
                                                   const BuildMapOptions& options) const;

  std::vector<MapPlane> map_;
  std::vector<char> grounded_;  // per group: MapPlane::grounded of the planes it places
  int mapped_count_ = 0;
};

}  // namespace relslam::plane
