#include "map_feed.hpp"

#include <cmath>
#include <stdexcept>

namespace relslam::point {

Rigid3 MapFeed::world_T_robot(int k) {
  if (k == 0) return Rigid3::identity();
  const Eigen::Matrix3d turn = rotation_about(Eigen::Vector3d::UnitY(), 0.004 * k);
  const Eigen::Matrix3d pitch = rotation_about(Eigen::Vector3d::UnitX(), 0.01 * std::sin(0.3 * k));
  return {turn * pitch, Eigen::Vector3d(0.05 * k, 0.02 * std::sin(0.2 * k), 0.3 * k)};
}

PointId MapFeed::add_landmark(const Eigen::Vector3d& world, int first, int last) {
  return add_landmark([world](int) { return world; }, first, last);
}

PointId MapFeed::add_landmark(std::function<Eigen::Vector3d(int)> world_at, int first, int last) {
  if (first <= fed_) throw std::logic_error("MapFeed: a landmark first seen in an iteration already fed");
  const auto id = static_cast<PointId>(map.points.size());
  map.points.emplace_back(options_.ring_capacity);
  map.points.back().id = id;
  map.points.back().creation_iteration = first;
  landmarks_.push_back({std::move(world_at), first, last});
  return id;
}

std::vector<PointId> MapFeed::add_landmarks(int n, int first, int last) {
  std::vector<PointId> ids;
  for (int i = 0; i < n; ++i) {
    const auto j = static_cast<double>(landmarks_.size());
    ids.push_back(add_landmark(Eigen::Vector3d(-20.0 + 37.0 * std::fmod(0.618034 * j, 1.0), 3.0 * std::sin(1.7 * j),
                                               20.0 + 40.0 * std::fmod(0.414214 * j + 0.1, 1.0)),
                               first, last));
  }
  return ids;
}

void MapFeed::feed_to(int k) {
  for (int t = fed_ + 1; t <= k; ++t) {
    map.charting.begin_iteration(t);
    if (map.first_iteration == kNone) map.first_iteration = t;
    map.iteration = t;
    for (std::size_t i = 0; i < landmarks_.size(); ++i) {
      const Landmark& l = landmarks_[i];
      if (t < l.first || t > l.last) continue;
      const auto id = static_cast<PointId>(i);
      RltPoint& p = map.points[i];
      const Point o{world_T_robot(t).inverse_apply(l.world_at(t)), t};
      p.observations.push(o);
      p.interval.add(t);
      map.charting.add(id);
      if (t != l.first) continue;
      p.first_observation = o;
      if (options_.temporary_group.enabled) map.temporary_list.push(id, t);
      if (options_.final_group.enabled) map.final_list.push(id, t);
    }
  }
  fed_ = k;
}

void MapFeed::place(PointId id) { map.set_global(id, truth(id, map.iteration)); }

}  // namespace relslam::point
