#include "relslam/plane/rlt_map_builder.hpp"

#include "pose_mean.hpp"

#include <cmath>

namespace relslam::plane {

void RltMapBuilder::build_map(std::span<const RltXPointLink> links, std::vector<RltXPoint>& xpoints,
                              const std::vector<RltPlane>& planes, const PlanarPose& world_T_start, bool anchor,
                              double same_length) {
  // Rebuilt from the links every iteration (spec §5.8): a group recomputed this iteration moves
  // every group chained after it.
  map_.assign(planes.size(), MapPlane{});
  mapped_count_ = 0;
  for (const RltXPointLink& link : links) {
    RltXPoint& to = xpoints[link.to];
    PoseMean world_T_to;
    if (link.first) {
      // Rule 4: X0's planes first seen in the earliest iteration were seen from the start pose,
      // so world_T_x0 = world_T_start ∘ P(first observation) ∘ (x0_T_plane)⁻¹, averaged over them.
      int earliest = 0;
      bool any = false;
      for (PlaneId p : to.planes()) {
        const RltXPointRef* ref = planes[p].ref(to.id());
        if (!ref->valid) continue;
        const int first = planes[p].created_iteration();
        if (!any || first < earliest) earliest = first;
        any = true;
      }
      for (PlaneId p : to.planes()) {
        const RltXPointRef* ref = planes[p].ref(to.id());
        if (!ref->valid || planes[p].created_iteration() != earliest) continue;
        const PlanarPose start_T_x = planes[p].first_observation().pose() * ref->pose.inverse();
        world_T_to.add(anchor ? world_T_start * start_T_x : PlanarPose::identity());
      }
    } else if (xpoints[link.from].placed()) {
      // Rule 8: each linking plane says where `to` is from where `from` put it; averaged.
      const RltXPoint& from = xpoints[link.from];
      for (PlaneId p : link.planes) {
        const RltXPointRef* in_from = planes[p].ref(from.id());
        const RltXPointRef* in_to = planes[p].ref(to.id());
        if (!in_from->valid || !in_to->valid) continue;
        // Part 2 grows the smaller of the two memberships to the larger size first (Rule 17).
        world_T_to.add(from.world_pose() * in_from->pose * in_to->pose.inverse());
      }
    }
    to.place(world_T_to.mean(), world_T_to.count() > 0);
    if (to.placed()) place_planes(to, planes, same_length);
  }
}

void RltMapBuilder::place_planes(const RltXPoint& xpoint, const std::vector<RltPlane>& planes, double same_length) {
  for (PlaneId p : xpoint.planes()) {
    const RltXPointRef* ref = planes[p].ref(xpoint.id());
    MapPlane& entry = map_[p];
    // The first group to place a plane keeps it unless a later one knows it larger [T].
    if (!ref->valid || (entry.mapped && ref->max_length <= entry.length + same_length)) continue;
    if (!entry.mapped) ++mapped_count_;
    entry.mapped = true;
    entry.world_T_plane = xpoint.world_pose() * ref->pose;
    entry.length = ref->max_length;
    entry.source = xpoint.id();
    entry.key_point = ref->key_point;
    const PlaneObject& seen = planes[p].latest();
    entry.plane = PlaneObject::from_pose(entry.world_T_plane, entry.length, seen.y_lo, seen.y_lo + ref->height);
  }
}

RltPoset RltMapBuilder::get_poset(std::span<const RegisteredObservation> observations, double same_length) const {
  PoseMean mean;
  for (const RegisteredObservation& o : observations) {
    const MapPlane& entry = map_[o.plane];
    // Part 2 grows a partial observation from its key point (Rule 16) or finds one (Rule 19).
    if (!entry.mapped || std::abs(entry.length - o.observation->length()) > same_length) continue;
    mean.add(calculate_offset(entry.plane, *o.observation));
  }
  return {mean.mean(), mean.count() > 0, mean.count()};
}

void RltMapBuilder::match_plane_to_map(int observation_index, const PlaneObject& observation,
                                       const PlanarPose& world_T_robot, const MatchBounds& bounds,
                                       bool same_normal_direction, const std::vector<char>& taken,
                                       std::vector<PlaneMatch>& out) const {
  // Deviation (spec §5.4.2 compares in the world): the map plane is brought into the robot
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
