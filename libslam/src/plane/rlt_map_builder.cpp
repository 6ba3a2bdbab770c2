#include "relslam/plane/rlt_map_builder.hpp"

#include "pose_mean.hpp"
#include "relslam/plane/calculate_missing_key_points.hpp"

#include <cmath>
#include <optional>

namespace relslam::plane {
namespace {

// `plane`'s key point at `iteration`: a membership's, when its comparison piece holds the
// iteration (a key point is valid only in its interval, Rule 19), else CalculateMissingKeyPoints
// against `others` in order. None when nothing tells. (A plane's own lengths cannot extend a
// piece: an end that leaves the view while the plane keeps shrinking shows no growth switch.)
// A membership's key point whose comparison piece holds `iteration`; None if there is none.
KeyPoint membership_key_point_at(const RltPlane& plane, int iteration) {
  // A motion model's key point held over its track, not at each iteration: at the turn's end the
  // end it held can be cut (Map E's fourth corner, iteration 1235: the start wall grown from the
  // wrong end, the pose 1.8 off).
  for (const RltXPointRef& ref : plane.refs())
    if (ref.valid && !ref.tracked && ref.key_point != KeyPoint::None && ref.interval.in_interval(iteration))
      return ref.key_point;
  return KeyPoint::None;
}

// Rule 19 off (rules.missing_key_points): the first membership's key point, whatever interval
// it was computed on, and none recomputed (the stale key points of Figs 90–92).
KeyPoint any_membership_key_point(const RltPlane& plane) {
  for (const RltXPointRef& ref : plane.refs())
    if (ref.valid && ref.key_point != KeyPoint::None) return ref.key_point;
  return KeyPoint::None;
}

KeyPoint key_point_at(const RltPlane& plane, int iteration, const std::vector<const RltPlane*>& others,
                      const GetPosetOptions& options) {
  if (const KeyPoint kp = membership_key_point_at(plane, iteration); kp != KeyPoint::None) return kp;
  if (!options.missing_key_points) return any_membership_key_point(plane);
  std::vector<ObservationView> views;
  views.reserve(others.size());
  for (const RltPlane* o : others)
    if (o != &plane) views.push_back(o->view());
  if (views.empty()) return KeyPoint::None;
  const std::optional<MissingKeyPoint> missing =
      calculate_missing_key_points(plane.view(), views, iteration, options.compare);
  return missing ? missing->key_point : KeyPoint::None;
}

}  // namespace

std::optional<PlanarPose> RltMapBuilder::first_observation_pose(const RltXPoint& x0, const RltPlane& plane,
                                                                const std::vector<RltPlane>& planes,
                                                                const BuildMapOptions& options) const {
  const PlaneObject& first = plane.first_observation();
  const RltXPointRef* ref = plane.ref(x0.id());
  if (!options.key_point.key_points || !options.first_reading_resize ||
      std::abs(first.length() - ref->max_length) <= options.key_point.same_length)
    return first.pose();
  // Rule 4's first reading smaller than the plane (Fig 90): grown to the size
  // in X0 from the key point valid in the first observation's piece, found against X0's planes.
  std::vector<const RltPlane*> others;
  for (PlaneId p : x0.planes()) others.push_back(&planes[p]);
  const KeyPoint kp = key_point_at(plane, first.iteration, others, options.key_point);
  if (kp == KeyPoint::None) return std::nullopt;  // cannot be grown: says nothing [R, thesis 4.3.4]
  return adjust_size(first, ref->max_length, kp).pose();
}

void RltMapBuilder::place_x0(const RltXPoint& x0, const std::vector<RltPlane>& planes,
                             const PlanarPose& world_T_start, const BuildMapOptions& options,
                             PoseMean& world_T_x0) const {
  // Rule 4: X0's planes first seen in the earliest iteration were seen from the start pose,
  // so world_T_x0 = world_T_start ∘ P(first observation) ∘ (x0_T_plane)⁻¹, averaged over them.
  int earliest = 0;
  bool any = false;
  for (PlaneId p : x0.planes()) {
    if (!planes[p].ref(x0.id())->valid) continue;
    const int first = planes[p].created_iteration();
    if (!any || first < earliest) earliest = first;
    any = true;
  }
  // A first observation that cannot be grown to the plane's size gives no estimate; when none
  // can, they are used as seen [R]. With observed_anchor only those grown from an end the sensor
  // did not cut (uncut_first_observation_pose), else the lines of two non-parallel ones
  // (lines_first_observation_pose), else none: X0 waits [C].
  enum class Pass { Uncut, Lines, Grown, AsSeen };
  for (Pass pass : {Pass::Uncut, Pass::Lines, Pass::Grown, Pass::AsSeen}) {
    if (world_T_x0.count() > 0 || (pass == Pass::Uncut || pass == Pass::Lines) != options.observed_anchor) continue;
    if (pass == Pass::Lines) {
      const std::optional<PlanarPose> lines = lines_first_observation_pose(x0, planes, earliest, world_T_start, options);
      if (lines) world_T_x0.add(options.anchor_first_observation ? *lines : PlanarPose::identity());
      continue;
    }
    for (PlaneId p : x0.planes()) {
      const RltXPointRef* ref = planes[p].ref(x0.id());
      if (!ref->valid || planes[p].created_iteration() != earliest) continue;
      const std::optional<PlanarPose> first = pass == Pass::Uncut   ? uncut_first_observation_pose(x0, planes[p], options)
                                              : pass == Pass::Grown ? first_observation_pose(x0, planes[p], planes, options)
                                                                    : planes[p].first_observation().pose();
      if (!first) continue;
      world_T_x0.add(options.anchor_first_observation ? world_T_start * *first * ref->pose.inverse()
                                                      : PlanarPose::identity());
    }
  }
}

std::optional<PlanarPose> RltMapBuilder::uncut_first_observation_pose(const RltXPoint& x0, const RltPlane& plane,
                                                                       const BuildMapOptions& options) const {
  // open_cut_ends (beyond Rule 4): the first reading says where X0 is exactly only through an end
  // the sensor saw as the wall's, grown to X0's size on that end, and only when X0 has the plane
  // anchored on the same end or whole. A first reading cut at both ends lies anywhere along the
  // wall from where X0's comparisons saw it (the robot may have driven along the wall in between).
  const PlaneObject& first = plane.first_observation();
  const RltXPointRef* ref = plane.ref(x0.id());
  const bool whole = plane.whole_length(true) <= ref->max_length + options.key_point.same_length;
  for (const KeyPoint end : {KeyPoint::Left, KeyPoint::Right}) {
    const bool cut = end == KeyPoint::Left ? first.a_cut : first.b_cut;
    if (!cut && (whole || ref->key_point == end)) return adjust_size(first, ref->max_length, end).pose();
  }
  return std::nullopt;
}

std::optional<PlanarPose> RltMapBuilder::lines_first_observation_pose(const RltXPoint& x0,
                                                                       const std::vector<RltPlane>& planes,
                                                                       int earliest, const PlanarPose& world_T_start,
                                                                       const BuildMapOptions& options) {
  // observed_anchor (beyond Rule 4): the first readings seen from the start pose, each on its
  // plane's line in X0, as a pose is put on the map's lines (fit_pose_to_lines): two lines more
  // than min_angle apart fix where X0 is whatever the readings' ends (a corner).
  std::vector<LinePair> pairs;
  for (PlaneId p : x0.planes()) {
    const RltXPointRef* ref = planes[p].ref(x0.id());
    if (!ref->valid || planes[p].created_iteration() != earliest) continue;
    const PlaneObject& first = planes[p].first_observation();
    pairs.push_back({PlaneObject::from_pose(ref->pose, ref->max_length, first.y_lo, first.y_hi),
                     first.transformed(world_T_start)});
  }
  return fit_pose_to_lines(pairs, options.min_angle_rad);
}

void RltMapBuilder::build_map(std::span<const RltXPointLink> links, std::vector<RltXPoint>& xpoints,
                              const std::vector<RltPlane>& planes, const PlanarPose& world_T_start,
                              const BuildMapOptions& options, std::span<const LinePlacement> lines) {
  // Rebuilt from the links every iteration (thesis 4.4.3.11): a group recomputed this iteration moves
  // every group chained after it.
  map_.assign(planes.size(), MapPlane{});
  grounded_.assign(xpoints.size(), 0);
  mapped_count_ = 0;
  for (const RltXPointLink& link : links) {
    RltXPoint& to = xpoints[link.to];
    PoseMean world_T_to;
    // A group linked from a motion model that is not grounded, through a grounded plane, is
    // placed from that plane's grounded entry (link_source), and is grounded.
    grounded_[link.to] = to.motion_model() ? to.track_trusted()
                         : link.first      ? true
                                           : link.from != kNone && !link.planes.empty() &&
                                            (grounded_[link.from] ||
                                             link_source(xpoints[link.from], link.planes.front(), options) != link.from);
    if (to.motion_model()) {
      // Rule 27: a motion-model group stays where the last valid pose put it.
      world_T_to.add(*to.anchor());
    } else if (link.first) {
      place_x0(to, planes, world_T_start, options, world_T_to);
    } else if (xpoints[link.from].placed()) {
      link_to(link, xpoints, planes, options, world_T_to);
    }
    if (options.place_by_lines && world_T_to.count() == 0 && !to.motion_model() && !link.first) {
      place_on_walls(to, planes, lines, options, world_T_to);
      if (world_T_to.count() > 0) grounded_[link.to] = 1;  // placed on walls a pose checked
    }
    to.place(world_T_to.mean(), world_T_to.count() > 0);
    if (to.placed()) place_planes(to, planes, grounded_[link.to] != 0, options);
  }
  if (options.place_by_lines) place_lines(lines);
}

void RltMapBuilder::place_on_walls(const RltXPoint& to, const std::vector<RltPlane>& planes,
                                   std::span<const LinePlacement> lines, const BuildMapOptions& options,
                                   PoseMean& world_T_to) const {
  std::vector<LinePair> pairs;
  for (PlaneId p : to.planes()) {
    const RltXPointRef* ref = planes[p].ref(to.id());
    if (!ref->valid) continue;
    const MapPlane& entry = map_[p];
    const PlaneObject seen = PlaneObject::from_pose(ref->pose, ref->max_length);
    if (entry.mapped && entry.grounded)
      pairs.push_back({seen, entry.plane});
    else if (!entry.mapped && p < static_cast<PlaneId>(lines.size()) && lines[p].placed)
      pairs.push_back({seen, lines[p].world});
  }
  if (const std::optional<PlanarPose> pose = place_on_lines(pairs, options.line)) world_T_to.add(*pose);
}

void RltMapBuilder::place_lines(std::span<const LinePlacement> lines) {
  for (std::size_t p = 0; p < lines.size() && p < map_.size(); ++p) {
    MapPlane& entry = map_[p];
    if (entry.mapped || !lines[p].placed) continue;
    ++mapped_count_;
    entry.mapped = true;
    entry.plane = lines[p].world;
    entry.world_T_plane = entry.plane.pose();
    entry.length = entry.plane.length();
    entry.grounded = true;  // from poses the lines of grounded walls fixed
  }
}

void RltMapBuilder::link_to(const RltXPointLink& link, const std::vector<RltXPoint>& xpoints,
                            const std::vector<RltPlane>& planes, const BuildMapOptions& options,
                            PoseMean& world_T_to) const {
  // Rule 8: each linking plane says where `to` is from where `from` put it; averaged.
  const RltXPoint& to = xpoints[link.to];
  const double same_length = options.key_point.same_length;
  bool refused = false;  // a linking plane whose two pieces do not share an end (below)
  for (PlaneId p : link.planes) {
    const RltXPoint& from = xpoints[link_source(xpoints[link.from], p, options)];
    const RltXPointRef* in_from = planes[p].ref(from.id());
    const RltXPointRef* in_to = planes[p].ref(to.id());
    if (!in_from->valid || !in_to->valid) continue;
    PlanarPose from_T_plane = in_from->pose, to_T_plane = in_to->pose;
    if (options.key_point.key_points && std::abs(in_from->max_length - in_to->max_length) > same_length) {
      // Rule 17: the smaller membership re-anchored to the larger size on its own key point;
      // without one it cannot be resized and the plane does not link (thesis 4.3.4).
      const bool from_smaller = in_from->max_length < in_to->max_length;
      const RltXPointRef* smaller = from_smaller ? in_from : in_to;
      const double larger = std::max(in_from->max_length, in_to->max_length);
      if (smaller->key_point == KeyPoint::None) continue;
      // Beyond the thesis (adaptive): the larger must hold the smaller's key-point end. Two
      // pieces of one wall, each with the other end real, say nothing about where along the
      // wall one lies from the other (Fig 87's L* is the wall's size only when one is whole).
      // With open_cut_ends a piece is whole when one uncut reading was as long (whole_length),
      // unless a motion model's track measured the extent (Rule 23: over many readings).
      const RltXPointRef* larger_ref = from_smaller ? in_to : in_from;
      const double whole = larger_ref->tracked ? planes[p].longest_seen() : planes[p].whole_length(options.cut_ends_open);
      if (options.prefer_grounded && !holds_end(larger_ref->size_static, larger_ref->key_point, larger_ref->max_length,
                                                smaller->key_point, whole, same_length)) {
        refused = true;
        continue;
      }
      (from_smaller ? from_T_plane : to_T_plane) = reanchor(smaller->pose, smaller->max_length, larger, smaller->key_point);
    }
    world_T_to.add(from.world_pose() * from_T_plane * to_T_plane.inverse());
  }
  // ... and then the link places nothing: the other linking planes' estimates come from the
  // same two groups, whose comparisons joined the refused plane's pieces as if they were one
  // size. Keeping them (even those the groups saw static: a piece the frustum cuts at both ends
  // keeps its length too) put wrong poses back on the generated rooms [C].
  if (refused) world_T_to = PoseMean{};
}

XPointId RltMapBuilder::link_source(const RltXPoint& from, PlaneId p, const BuildMapOptions& options) const {
  // Beyond the thesis (prefer_grounded): a motion model links a new group through its one plane
  // (thesis 4.3.2), which is on the map already — the motion model starts only on a mapped plane
  // (Rule 26). Where the motion model's group puts that plane is its track's guess; where the
  // map has it, placed by a grounded group, is not. So the link goes through that group.
  if (!options.prefer_grounded || !from.motion_model() || grounded_[from.id()]) return from.id();
  const MapPlane& entry = map_[p];
  return entry.mapped && entry.grounded && entry.source != kNone ? entry.source : from.id();
}

void RltMapBuilder::place_planes(const RltXPoint& xpoint, const std::vector<RltPlane>& planes, bool grounded,
                                 const BuildMapOptions& options) {
  const double same_length = options.key_point.same_length;
  for (PlaneId p : xpoint.planes()) {
    const RltXPointRef* ref = planes[p].ref(xpoint.id());
    MapPlane& entry = map_[p];
    // Part 2: a plane that changed size and has no key point has no known anchor (thesis 4.3.4).
    if (options.key_point.key_points && ref->key_point == KeyPoint::None && !ref->size_static) continue;
    if (!ref->valid) continue;
    // The first group to place a plane keeps it unless a later one knows it larger [T]; with
    // prefer_grounded a grounded placement comes before any through a motion model [C].
    const bool rank_decides = options.prefer_grounded && entry.mapped && entry.grounded != grounded;
    if (rank_decides ? entry.grounded : entry.mapped && ref->max_length <= entry.length + same_length) continue;
    if (!entry.mapped) ++mapped_count_;
    entry.mapped = true;
    entry.world_T_plane = xpoint.world_pose() * ref->pose;
    entry.length = ref->max_length;
    entry.source = xpoint.id();
    entry.key_point = ref->key_point;
    entry.size_static = ref->size_static;
    entry.grounded = grounded || !options.prefer_grounded;  // without grounded_map every plane counts
    const PlaneObject& seen = planes[p].latest();
    entry.plane = PlaneObject::from_pose(entry.world_T_plane, entry.length, seen.y_lo, seen.y_lo + ref->height);
  }
}

RltPoset RltMapBuilder::get_poset(std::span<const RegisteredObservation> observations,
                                  const std::vector<RltPlane>& planes, const GetPosetOptions& options) const {
  PoseMean mean;
  std::vector<const RegisteredObservation*> bad;
  std::vector<const RltPlane*> good_planes;
  const auto add = [&](const RegisteredObservation& o, const PlaneObject& seen) {
    mean.add(calculate_offset(map_[o.plane].plane, seen));
    good_planes.push_back(&planes[o.plane]);
  };
  for (const RegisteredObservation& o : observations) {
    const MapPlane& entry = map_[o.plane];
    if (!entry.mapped) continue;
    if (std::abs(entry.length - o.observation->length()) <= options.same_length) {
      // The same size within τ_len; a known key point still grows it the last bit exactly (an
      // end cut by less than τ_len would otherwise move the midpoint by half the cut).
      const KeyPoint kp =
          options.key_points ? membership_key_point_at(planes[o.plane], o.observation->iteration) : KeyPoint::None;
      add(o, kp == KeyPoint::None ? *o.observation : adjust_size(*o.observation, entry.length, kp));
      continue;
    }
    if (!options.key_points) continue;  // part 1: full-size observations only
    // Rule 16: grown (or shrunk) to the map's size from its key point at this iteration.
    const KeyPoint kp = key_point_at(planes[o.plane], o.observation->iteration, {}, options);
    if (kp == KeyPoint::None) {
      bad.push_back(&o);
      continue;
    }
    if (entry.holds_end(kp, planes[o.plane].longest_seen(), options.same_length))
      add(o, adjust_size(*o.observation, entry.length, kp));
  }
  // Rule 19 for the rest: key points from comparisons with the good planes of this iteration,
  // then with the other bad ones (thesis 4.4.3.11).
  for (const RegisteredObservation* o : bad) {
    std::vector<const RltPlane*> others = good_planes;
    for (const RegisteredObservation* b : bad)
      if (b != o) others.push_back(&planes[b->plane]);
    const KeyPoint kp = key_point_at(planes[o->plane], o->observation->iteration, others, options);
    if (kp != KeyPoint::None && map_[o->plane].holds_end(kp, planes[o->plane].longest_seen(), options.same_length))
      mean.add(calculate_offset(map_[o->plane].plane, adjust_size(*o->observation, map_[o->plane].length, kp)));
  }
  return {mean.mean(), mean.count() > 0, mean.count()};
}

void RltMapBuilder::match_plane_to_map(int observation_index, const PlaneObject& observation,
                                       const PlanarPose& world_T_robot, const MatchBounds& bounds,
                                       bool same_normal_direction, const std::vector<char>& taken,
                                       std::vector<PlaneMatch>& out) const {
  // Deviation (thesis 4.3.1 compares in the world): the map plane is brought into the robot
  // frame instead, so the offset test measures the distance to the robot as local matching
  // does. In the world frame a heading error of the previous pose moves a plane's offset by
  // the robot's distance from the world origin times the error, which rejects correct
  // matches far from the origin while turning.
  const PlanarPose robot_T_world = world_T_robot.inverse();
  for (PlaneId p = 0; p < static_cast<PlaneId>(map_.size()); ++p) {
    if (!map_[p].mapped || taken[p]) continue;
    PlaneObject predicted = map_[p].plane.transformed(robot_T_world);
    predicted.iteration = observation.iteration;
    const double score = match_plane(predicted, observation, bounds, same_normal_direction);
    if (score >= 0) out.push_back({observation_index, p, score});
  }
}

}  // namespace relslam::plane
