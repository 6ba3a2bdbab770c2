#include "relslam/spatial/incremental_ovlp_quadtree.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace relslam::spatial {

IncrementalOVLPQuadTree::IncrementalOVLPQuadTree(double cell_size, double overlap)
    : cell_(cell_size), overlap_(overlap) {
  if (!(cell_size > 0) || !(overlap >= 0) || overlap > cell_size)
    throw std::logic_error("IncrementalOVLPQuadTree: need 0 <= overlap <= cell size, got overlap " +
                           std::to_string(overlap) + ", cell " + std::to_string(cell_size));
}

std::uint64_t IncrementalOVLPQuadTree::key(std::int64_t ix, std::int64_t iz) const {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(ix)) << 32) | static_cast<std::uint32_t>(iz);
}

IncrementalOVLPQuadTree::Membership IncrementalOVLPQuadTree::cells_of(const Eigen::Vector3d& p) const {
  const auto ix = static_cast<std::int64_t>(std::floor(p.x() / cell_));
  const auto iz = static_cast<std::int64_t>(std::floor(p.z() / cell_));
  const double fx = p.x() - ix * cell_, fz = p.z() - iz * cell_;
  const int lo_x = fx <= overlap_ ? -1 : 0, hi_x = cell_ - fx <= overlap_ ? 1 : 0;
  const int lo_z = fz <= overlap_ ? -1 : 0, hi_z = cell_ - fz <= overlap_ ? 1 : 0;
  Membership m;
  for (int dz = lo_z; dz <= hi_z; ++dz)
    for (int dx = lo_x; dx <= hi_x; ++dx) m.cells[m.count++] = key(ix + dx, iz + dz);
  return m;
}

void IncrementalOVLPQuadTree::place(int id, const Eigen::Vector3d& p) {
  if (id < 0) throw std::logic_error("IncrementalOVLPQuadTree: negative id");
  if (static_cast<std::size_t>(id) >= members_.size()) members_.resize(static_cast<std::size_t>(id) * 2 + 16);
  const Membership next = cells_of(p);
  Membership& current = members_[id];
  // A move within the same cells changes nothing: positions are read live by the caller.
  if (current.count == next.count &&
      std::equal(next.cells.begin(), next.cells.begin() + next.count, current.cells.begin()))
    return;
  if (current.count > 0) remove(id);
  for (int i = 0; i < next.count; ++i) cells_[next.cells[i]].push_back(id);
  members_[id] = next;
  ++count_;
}

void IncrementalOVLPQuadTree::remove(int id) {
  if (!contains(id)) return;
  Membership& m = members_[id];
  for (int i = 0; i < m.count; ++i) {
    auto cell = cells_.find(m.cells[i]);
    auto& ids = cell->second;
    const auto it = std::find(ids.begin(), ids.end(), id);
    *it = ids.back();
    ids.pop_back();
    if (ids.empty()) cells_.erase(cell);
  }
  m.count = 0;
  --count_;
}

bool IncrementalOVLPQuadTree::contains(int id) const {
  return id >= 0 && static_cast<std::size_t>(id) < members_.size() && members_[id].count > 0;
}

std::span<const int> IncrementalOVLPQuadTree::query(const Eigen::Vector3d& q) {
  const auto it = cells_.find(
      key(static_cast<std::int64_t>(std::floor(q.x() / cell_)), static_cast<std::int64_t>(std::floor(q.z() / cell_))));
  if (it == cells_.end()) return {};
  return it->second;
}

}  // namespace relslam::spatial
