#include "relslam/point/rlt_map.hpp"

#include <algorithm>

namespace relslam::point {
namespace {

constexpr double kBasisEpsilon = 1e-6;  // relative degeneracy tolerance of one iteration's basis [C]

}  // namespace

RltMap::RltMap(const PointSlamOptions& options)
    : charting(options.charting_capacity),
      global_index(spatial::make_global_index(options.global_index, options.global_cell_size,
                                              std::max(options.global_bound, options.merge_bound))) {}

void RltMap::compute(RltGroup& group, int from, int k) {
  if (group.accumulate(points, from, k, kBasisEpsilon)) anchor(group);
}

void RltMap::anchor(RltGroup& group) {
  const auto world_T_group = group.registration(points, first_iteration);
  if (!world_T_group) return;
  for (std::size_t i = 0; i < group.members().size(); ++i) {
    const PointId id = group.members()[i];
    const RltPoint& p = points[id];
    if (group.anchor(static_cast<int>(i)) || p.owner != group.id() || p.dynamic || p.merged) continue;
    set_global(id, *world_T_group * group.relative(static_cast<int>(i)));
  }
}

void RltMap::set_global(PointId id, const Eigen::Vector3d& g) {
  RltPoint& p = points[id];
  p.global = g;
  p.has_global = true;
  p.has_provisional = false;
  any_mapped = true;
  global_index->place(id, g);
  mark_changed(id);
}

void RltMap::retire(RltGroup& group) {
  group.retire();
  --stats.alive;
  stats.alive_members -= static_cast<long long>(group.members().size());
  if (group.level() == GroupLevel::Temporary) --stats.temporary_alive;
  for (PointId id : group.members()) {
    auto& refs = points[id].groups;
    refs.erase(std::remove_if(refs.begin(), refs.end(), [&](const RltGroupRef& r) { return r.group == group.id(); }),
               refs.end());
  }
}

void RltMap::mark_changed(PointId id) {
  if (changed_at_.size() <= static_cast<std::size_t>(id))
    changed_at_.resize(static_cast<std::size_t>(id) * 2 + 16, kNone);
  if (changed_at_[id] == iteration) return;
  changed_at_[id] = iteration;
  changed_.push_back(id);
}

std::vector<PointId> RltMap::take_changed() {
  std::vector<PointId> changed;
  changed.swap(changed_);
  return changed;
}

}  // namespace relslam::point
