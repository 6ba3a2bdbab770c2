#include "relslam/point/group_relaxation.hpp"

#include "relslam/point/rlt_map.hpp"

#include <cmath>

namespace relslam::point {

MapRelaxation build_relaxation(const RltMap& map, double loss_scale) {
  MapRelaxation out;
  out.problem.loss_scale = loss_scale;
  std::vector<int> index(map.groups.size(), kNone);  // map group id -> problem index
  for (const RltGroup& g : map.groups) {
    if (!g.alive()) continue;
    const auto world_T_group = g.registration(map.points, map.first_iteration);
    if (!world_T_group) continue;
    index[g.id()] = static_cast<int>(out.groups.size());
    out.groups.push_back(g.id());
    out.problem.world_T_group.push_back(*world_T_group);
    // Deviation: the root (and provisional roots) keep the thesis's map frame.
    out.problem.fixed.push_back(g.root());
  }
  for (const RltPoint& p : map.points) {
    if (p.dynamic || p.merged || p.groups.size() < 2) continue;
    // The owner (whose estimate is the map position) first, then every other group: a star of
    // ties, one per extra group.
    const RltGroupRef* hub = nullptr;
    for (const RltGroupRef& r : p.groups)
      if (index[r.group] != kNone && (hub == nullptr || r.group == p.owner)) hub = &r;
    if (hub == nullptr) continue;
    const RltGroup& hub_group = map.groups[hub->group];
    for (const RltGroupRef& r : p.groups) {
      if (&r == hub || index[r.group] == kNone) continue;
      const RltGroup& other = map.groups[r.group];
      const double weight = 1.0 / std::sqrt(1.0 / hub_group.iterations_used() + 1.0 / other.iterations_used());
      out.problem.ties.push_back(
          {index[hub->group], hub_group.relative(hub->member), index[r.group], other.relative(r.member), weight});
    }
  }
  return out;
}

int apply_relaxation(RltMap& map, const MapRelaxation& relaxation) {
  int moved = 0;
  for (std::size_t i = 0; i < relaxation.groups.size(); ++i) {
    const RltGroup& g = map.groups[relaxation.groups[i]];
    const Rigid3& world_T_group = relaxation.problem.world_T_group[i];
    for (std::size_t m = 0; m < g.members().size(); ++m) {
      const PointId id = g.members()[m];
      const RltPoint& p = map.points[id];
      if (g.anchor(static_cast<int>(m)) || p.owner != g.id() || !p.on_map()) continue;
      map.set_global(id, world_T_group * g.relative(static_cast<int>(m)));
      ++moved;
    }
  }
  return moved;
}

}  // namespace relslam::point
