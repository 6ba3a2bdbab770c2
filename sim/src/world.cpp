#include "relslam/sim/world.hpp"

#include "relslam/sim/random.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace relslam::sim {
namespace {

// Point j of the band depends on key j only, so a denser field with the same seed contains
// the sparser one: density sweeps compare like with like.
Eigen::Vector3d band_point(const SimOptions& o, const Path& path, std::uint64_t seed, int j) {
  RandomSequence rng(seed, Stream::Field, static_cast<std::uint64_t>(j));
  const double s = rng.uniform(0.0, path.field_length());
  const double lateral = rng.uniform(-o.band_half_width, o.band_half_width);
  const double vertical = rng.uniform(-o.band_half_height, o.band_half_height);  // symmetric, thesis 6.6.1
  const CenterlinePoint c = path.centerline(s);
  return c.position + lateral * c.left + vertical * Eigen::Vector3d::UnitY();
}

DynamicMotion random_motion(const DynamicOptions& d, RandomSequence& rng) {
  DynamicMotion m;
  m.amplitude = {d.amplitude, d.vertical_ratio * d.amplitude, d.amplitude};
  for (int axis = 0; axis < 3; ++axis) {
    m.period[axis] = rng.uniform(d.period_min, d.period_max);
    m.phase[axis] = rng.uniform(0.0, 2.0 * std::numbers::pi);
  }
  return m;
}

// Partial Fisher–Yates: `count` distinct entries of `pool`, in draw order.
std::vector<int> choose(std::vector<int> pool, int count, RandomSequence& rng) {
  for (int i = 0; i < count; ++i) {
    const auto j = i + static_cast<int>(rng.below(pool.size() - i));
    std::swap(pool[i], pool[j]);
  }
  pool.resize(count);
  return pool;
}

}  // namespace

Eigen::Vector3d DynamicMotion::offset(int k) const {
  Eigen::Vector3d o;
  for (int axis = 0; axis < 3; ++axis)
    o[axis] = amplitude[axis] * std::sin(2.0 * std::numbers::pi * k / period[axis] + phase[axis]);
  return o;
}

World::World(const SimOptions& o, const Path& path, std::uint64_t seed) {
  const auto n = static_cast<int>(landmark_count(o));
  anchors_.reserve(n);
  for (int j = 0; j < n; ++j) anchors_.push_back(band_point(o, path, seed, j));
  motion_index_.assign(n, -1);

  const DynamicOptions& d = o.dynamic;
  if (d.count == 0 && d.fraction == 0.0) return;
  std::vector<int> pool;
  int wanted = 0;
  if (d.count > 0) {
    // Among the points seen at iteration 0 and still seen count_visible_for iterations later
    // (noise-free), like the thesis's early movers that stayed in view.
    const int later = std::min(d.count_visible_for, path.iterations() - 1);
    const Rigid3 start = path.world_T_robot(0), then = path.world_T_robot(later);
    for (int j = 0; j < n; ++j)
      if (o.frustum.contains(start.inverse_apply(anchors_[j])) && o.frustum.contains(then.inverse_apply(anchors_[j])))
        pool.push_back(j);
    wanted = d.count;
    if (wanted > static_cast<int>(pool.size()))
      throw OptionError("dynamic.count", std::to_string(wanted) + " dynamic points requested but only " +
                                             std::to_string(pool.size()) + " points are visible at iteration 0 and " +
                                             std::to_string(later));
  } else {
    for (int j = 0; j < n; ++j) pool.push_back(j);
    wanted = static_cast<int>(std::lround(d.fraction * n));
  }
  RandomSequence rng(seed, Stream::Dynamics);
  std::vector<int> chosen = choose(std::move(pool), wanted, rng);
  std::sort(chosen.begin(), chosen.end());
  for (int id : chosen) {
    motion_index_[id] = static_cast<int>(motions_.size());
    RandomSequence motion_rng(seed, Stream::Dynamics, 1, static_cast<std::uint64_t>(id));
    motions_.push_back(random_motion(d, motion_rng));
  }
}

std::vector<int> World::dynamic_ids() const {
  std::vector<int> ids;
  for (int id = 0; id < size(); ++id)
    if (is_dynamic(id)) ids.push_back(id);
  return ids;
}

}  // namespace relslam::sim
